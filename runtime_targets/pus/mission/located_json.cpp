// A SAX pass over nlohmann's parser that builds the document and records where each value
// starts: the parser reads its input through an iterator that counts the octets consumed.
#include "detail/located_json.h"

#include <cstdint>
#include <iterator>
#include <set>
#include <vector>

namespace smcbip::pus::mission::detail {
namespace {

using nlohmann::json;

/// A char iterator that records the furthest offset it has been advanced to.
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* base, const char* p, std::size_t* furthest)
      : base_(base), p_(p), furthest_(furthest) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    ++p_;
    const auto consumed = static_cast<std::size_t>(p_ - base_);
    if (consumed > *furthest_) *furthest_ = consumed;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  friend bool operator==(const CountingIterator& a, const CountingIterator& b) {
    return a.p_ == b.p_;
  }

 private:
  const char* base_ = nullptr;
  const char* p_ = nullptr;
  std::size_t* furthest_ = nullptr;
};

/// Forwards the events to nlohmann's DOM builder and records offsets by JSON pointer. A token
/// starts at the first octet after the previous event's end that is not blank, ':' or ','
/// (the lexer may have read one octet past a number, which is never part of the next token).
class LocatingHandler {
 public:
  LocatingHandler(std::string_view text, const std::size_t* consumed, LocatedJson* out)
      : text_(text), consumed_(consumed), out_(out), dom_(out->value, true) {}

  bool null() { return value_start() && dom_.null(); }
  bool boolean(bool v) { return value_start() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return value_start() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) {
    return value_start() && dom_.number_unsigned(v);
  }
  bool number_float(json::number_float_t v, const std::string& s) {
    return value_start() && dom_.number_float(v, s);
  }
  bool string(std::string& v) { return value_start() && dom_.string(v); }
  bool binary(json::binary_t& v) { return value_start() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    const std::string path = current_path();
    if (!value_start()) return false;
    frames_.push_back(Frame{path, false, 0, {}, {}});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    const std::size_t at = token_start();
    Frame& frame = frames_.back();
    if (!frame.keys.insert(k).second) {
      error_ = JsonSyntaxError{at, "duplicate key \"" + k + "\""};
      return false;
    }
    frame.member = frame.path + "/" + escape_pointer_token(k);
    out_->key_offsets[frame.member] = at;
    last_end_ = *consumed_;
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    last_end_ = *consumed_;
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    const std::string path = current_path();
    if (!value_start()) return false;
    frames_.push_back(Frame{path, true, 0, {}, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    last_end_ = *consumed_;
    return dom_.end_array();
  }
  bool parse_error(std::size_t position, const std::string& /*last_token*/,
                   const nlohmann::detail::exception& ex) {
    std::string message = ex.what();
    // Drop nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 5: ".
    if (const auto column = message.find("column "); column != std::string::npos) {
      if (const auto colon = message.find(": ", column); colon != std::string::npos) {
        message = message.substr(colon + 2);
      }
    }
    error_ = JsonSyntaxError{position == 0 ? 0 : position - 1, message};
    return false;
  }

  const std::optional<JsonSyntaxError>& error() const { return error_; }

 private:
  struct Frame {
    std::string path;
    bool array = false;
    std::size_t next_index = 0;
    std::string member;
    std::set<std::string> keys;
  };

  std::string current_path() const {
    if (frames_.empty()) return "";
    const Frame& frame = frames_.back();
    return frame.array ? frame.path + "/" + std::to_string(frame.next_index) : frame.member;
  }
  bool value_start() {
    out_->value_offsets[current_path()] = token_start();
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next_index;
    last_end_ = *consumed_;
    return true;
  }
  std::size_t token_start() const {
    std::size_t at = last_end_;
    while (at < text_.size() && (text_[at] == ' ' || text_[at] == '\t' || text_[at] == '\n' ||
                                 text_[at] == '\r' || text_[at] == ':' || text_[at] == ',')) {
      ++at;
    }
    return at;
  }

  std::string_view text_;
  const std::size_t* consumed_;
  LocatedJson* out_;
  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Frame> frames_;
  std::size_t last_end_ = 0;
  std::optional<JsonSyntaxError> error_;
};

}  // namespace

std::size_t LocatedJson::offset_of(const std::string& pointer) const {
  std::string path = pointer;
  while (true) {
    if (const auto key = key_offsets.find(path); key != key_offsets.end()) return key->second;
    if (const auto value = value_offsets.find(path); value != value_offsets.end()) {
      return value->second;
    }
    if (path.empty()) return 0;
    path.resize(path.rfind('/'));
  }
}

std::variant<LocatedJson, JsonSyntaxError> parse_located(std::string_view text) {
  LocatedJson out;
  std::size_t consumed = 0;
  LocatingHandler handler(text, &consumed, &out);
  const CountingIterator first(text.data(), text.data(), &consumed);
  const CountingIterator last(text.data(), text.data() + text.size(), &consumed);
  if (!json::sax_parse(first, last, &handler)) {
    if (handler.error()) return *handler.error();
    return JsonSyntaxError{consumed, "malformed JSON"};
  }
  return out;
}

std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

std::string escape_pointer_token(std::string_view token) {
  std::string out;
  for (const char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace smcbip::pus::mission::detail
