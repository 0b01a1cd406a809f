// Reading the JSON lines of a recorded run step by step, every fault located.
#include "monitors/trace/detail/trace_reader.h"

#include <algorithm>
#include <cmath>

namespace smcbip::monitors {

namespace {

ErrorLocation first_fault(const std::string& path, const std::vector<TraceFault>& faults) {
  if (faults.empty()) return {path};
  return {path, static_cast<std::uint32_t>(faults.front().line),
          static_cast<std::uint32_t>(faults.front().column)};
}

}  // namespace

TraceError::TraceError(std::string path, std::vector<TraceFault> faults, std::size_t more)
    : InputError(faults.empty() ? std::string("not a trace") : faults.front().message,
                 first_fault(path, faults)),
      path(std::move(path)),
      faults(std::move(faults)),
      more(more) {}

std::string TraceError::report() const {
  std::string out;
  for (const TraceFault& f : faults) {
    out += bipc::position_text(path, f.line, f.column) + ": error: " + f.message + "\n";
  }
  if (more > 0) out += path + ": error: " + std::to_string(more) + " more errors not shown\n";
  return out;
}

namespace detail {

namespace {

using Json = nlohmann::json;

/// A string of the trace quoted for a message: JSON-escaped, and cut after 40 bytes (at a
/// character's start) so that a long value does not flood the message.
std::string quoted(const std::string& text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return Json(text).dump();
  std::size_t cut = kShown;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return Json(text.substr(0, cut)).dump() + "...";
}

/// Walks a line already known to be valid JSON.
class Scanner {
 public:
  Scanner(std::string_view text, std::size_t at) : t_(text), i_(at) {}

  std::size_t at() const { return i_; }
  bool done() const { return i_ >= t_.size(); }
  char peek() const { return done() ? '\0' : t_[i_]; }
  void skip(char c) {
    space();
    if (peek() == c) ++i_;
  }
  void space() {
    while (!done() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\r' || t_[i_] == '\n')) ++i_;
  }
  /// The raw text of the string that starts here, quotes included, and moves past it.
  std::string_view string() {
    const std::size_t start = i_++;
    while (!done() && t_[i_] != '"') i_ += t_[i_] == '\\' ? 2 : 1;
    i_ = std::min(i_ + 1, t_.size());
    return t_.substr(start, i_ - start);
  }
  void value() {
    space();
    if (peek() == '"') {
      string();
      return;
    }
    int depth = 0;
    while (!done()) {
      const char c = t_[i_];
      if (c == '"') {
        string();
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if (c == '}' || c == ']') {
        if (depth == 0) return;
        --depth;
      }
      if (c == ',' && depth == 0) return;
      ++i_;
      if (depth == 0 && (c == '}' || c == ']')) return;
    }
  }

 private:
  std::string_view t_;
  std::size_t i_;
};

/// Whether the raw JSON string `token` (with its quotes) spells `key`.
bool spells(std::string_view token, const std::string& key) {
  const std::string_view raw = token.substr(1, token.size() >= 2 ? token.size() - 2 : 0);
  if (raw.find('\\') == std::string_view::npos) return raw == key;
  const Json decoded = Json::parse(token, nullptr, /*allow_exceptions=*/false);
  return decoded.is_string() && decoded.get_ref<const std::string&>() == key;
}

const char* type_text(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "a list";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::boolean:
      return "a boolean";
    default:
      return "a number";
  }
}

}  // namespace

std::size_t value_column(std::string_view text, const std::vector<std::string>& keys) {
  std::size_t at = 0;
  for (const std::string& key : keys) {
    Scanner s(text, at);
    s.space();
    if (s.peek() != '{') return 0;
    s.skip('{');
    std::optional<std::size_t> value_at;
    s.space();
    while (s.peek() == '"') {
      const bool match = spells(s.string(), key);
      s.skip(':');
      s.space();
      if (match) value_at = s.at();
      s.value();
      s.skip(',');
      s.space();
    }
    if (!value_at) return 0;
    at = *value_at;
  }
  return keys.empty() ? 0 : at + 1;
}

std::optional<Json> TraceReader::next() {
  while (std::getline(in_, text_)) {
    ++line_;
    if (text_.find_first_not_of(" \t\r") == std::string::npos) continue;
    const bool first = !any_line_;
    any_line_ = true;
    if (!end_.empty()) {
      fault_at(1, "nothing may follow the end line (line " + std::to_string(end_line_) + ")");
      continue;
    }
    Json line;
    try {
      line = Json::parse(text_);
    } catch (const Json::parse_error& e) {
      // e.byte counts the bytes read, the offending one included.
      fault_at(std::clamp<std::size_t>(e.byte, 1, text_.size() + 1),
               "expected a JSON object on one line");
      continue;
    } catch (const Json::out_of_range& e) {
      // A number beyond the doubles ("1e400"): nlohmann names it, not where it is.
      const std::string what = e.what();
      const std::size_t open = what.find('\''), close = what.rfind('\'');
      const std::size_t at =
          open < close ? text_.find(what.substr(open + 1, close - open - 1)) : std::string::npos;
      fault_at(at == std::string::npos ? 1 : at + 1, "a number out of the range of doubles");
      continue;
    }
    if (!line.is_object()) {
      fault_at(text_.find_first_not_of(" \t\r") + 1, "expected a JSON object on one line");
      continue;
    }
    if (line.contains("header")) {
      check_header(line, first);
      continue;
    }
    if (line.contains("end")) {
      check_end(line);
      continue;
    }
    if (!check_step(line) || !check_required(line)) continue;
    any_step_ = true;
    return line;
  }
  return std::nullopt;
}

void TraceReader::require(std::vector<std::string> data, std::vector<std::string> atoms) {
  data_ = std::move(data);
  atoms_ = std::move(atoms);
  // The step returned last was read before these were known.
  if (any_step_) check_required(Json::parse(text_, nullptr, /*allow_exceptions=*/false));
}

void TraceReader::finish() const {
  if (!faults_.empty()) throw TraceError(path_, faults_, more_);
}

bool TraceReader::check_end(const Json& line) {
  const Json& end = line["end"];
  if (!end.is_string()) {
    return fault_at(column({"end"}),
                    std::string("expected \"end\" to be a string, got ") + type_text(end));
  }
  const std::string& reason = end.get_ref<const std::string&>();
  if (std::find(std::begin(kEndReasons), std::end(kEndReasons), reason) == std::end(kEndReasons)) {
    return fault_at(column({"end"}), "unknown end " + quoted(reason) +
                                         ": expected deadlock, timelock, limit, stopped or error");
  }
  end_ = reason;
  end_line_ = line_;
  return true;
}

bool TraceReader::check_header(const Json& line, bool first) {
  if (!first) return fault_at(column({"header"}), "the header must be the first line");
  const Json& header = line["header"];
  if (!header.is_object()) {
    return fault_at(column({"header"}),
                    std::string("expected \"header\" to be an object, got ") + type_text(header));
  }
  const auto clocks = header.find("clocks");
  if (clocks == header.end()) return true;
  if (!clocks->is_object()) {
    return fault_at(
        column({"header", "clocks"}),
        std::string("expected the header's \"clocks\" to be an object, got ") + type_text(*clocks));
  }
  for (const auto& [name, clock] : clocks->items()) {
    const auto unit = clock.is_object() ? clock.find("unit_ns") : clock.end();
    if (!clock.is_object() || unit == clock.end() || !unit->is_number() ||
        !(unit->get<double>() > 0)) {
      return fault_at(column({"header", "clocks", name}),
                      "expected clock " + quoted(name) + " to give its unit as \"unit_ns\" > 0");
    }
    clocks_[name] = unit->get<double>();
  }
  return true;
}

bool TraceReader::check_step(const Json& line) {
  const auto time = line.find("time");
  if (time == line.end()) return fault_at(column({}), "expected a number \"time\"");
  if (!time->is_number()) {
    return fault_at(column({"time"}),
                    std::string("expected a number \"time\", got ") + type_text(*time));
  }
  if (const auto fired = line.find("fired");
      fired != line.end() && !fired->is_null() && !fired->is_string()) {
    return fault_at(
        column({"fired"}),
        std::string("expected \"fired\" to be a string or null, got ") + type_text(*fired));
  }
  for (const char* part : {"places", "data", "rates"}) {
    if (const auto found = line.find(part); found != line.end() && !found->is_object()) {
      return fault_at(column({part}), std::string("expected \"") + part +
                                          "\" to be an object, got " + type_text(*found));
    }
  }
  if (const auto rates = line.find("rates"); rates != line.end()) {
    for (const auto& [clock, rate] : rates->items()) {
      if (!rate.is_number()) {
        return fault_at(column({"rates", clock}), "the rate of " + quoted(clock) + " is " +
                                                      type_text(rate) + ", expected a number");
      }
    }
  }
  const double scaled = time->get<double>() * ticks_per_unit_;
  if (!(std::abs(scaled) < 1e15)) return fault_at(column({"time"}), "the time is out of range");
  const auto ticks = static_cast<online::Tick>(std::llround(scaled));
  if (any_step_ && ticks < last_) return fault_at(column({"time"}), "the time goes back");
  ticks_ = ticks;
  last_ = std::max(last_, ticks);
  if (!any_step_) last_ = ticks;
  return true;
}

bool TraceReader::check_required(const Json& line) {
  if (data_.empty() && atoms_.empty()) return true;
  const auto data = line.find("data");
  for (const std::string& key : data_) {
    const auto value = data == line.end() ? line.end() : data->find(key);
    if (data == line.end() || value == data->end()) {
      return fault_at(column({"data"}), "no data " + quoted(key) + ", which the first step has");
    }
    if (!value->is_number() && !value->is_boolean()) {
      return fault_at(column({"data", key}), "data " + quoted(key) + " is " + type_text(*value) +
                                                 ", expected a number or a boolean");
    }
  }
  const auto places = line.find("places");
  for (const std::string& atom : atoms_) {
    const auto marked = places == line.end() ? line.end() : places->find(atom);
    if (places == line.end() || marked == places->end()) {
      return fault_at(column({"places"}),
                      "no places of " + quoted(atom) + ", which the first step has");
    }
    const bool names =
        marked->is_array() &&
        std::all_of(marked->begin(), marked->end(), [](const Json& p) { return p.is_string(); });
    if (!names) {
      return fault_at(column({"places", atom}),
                      "the places of " + quoted(atom) + " are not a list of names");
    }
  }
  return true;
}

bool TraceReader::fault_at(std::size_t column, const std::string& message) {
  if (faults_.size() < kMaxTraceFaults) {
    faults_.push_back({std::max<std::size_t>(line_, 1), column, message});
  } else {
    ++more_;
  }
  return false;
}

std::size_t TraceReader::column(const std::vector<std::string>& keys) const {
  const std::size_t found = keys.empty() ? 0 : value_column(text_, keys);
  return found != 0 ? found : text_.find_first_not_of(" \t\r") + 1;
}

}  // namespace detail
}  // namespace smcbip::monitors
