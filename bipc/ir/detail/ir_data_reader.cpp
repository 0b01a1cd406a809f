// Reading the typed fields of the IR data encoding, with the path of each for messages.
#include "bipc/ir/detail/ir_data_reader.h"

#include <bit>
#include <charconv>
#include <cmath>

#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir::detail {

using nlohmann::json;

std::string Path::text() const {
  if (parent == nullptr) return "(top)";
  std::string prefix = parent->parent == nullptr ? std::string() : parent->text();
  if (element) return prefix + "[" + std::to_string(index) + "]";
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

void fail(const Path& path, const std::string& what) {
  throw IrDataError{path.text() + ": " + what};
}

std::string got(const json& value) { return std::string(", got ") + value.type_name(); }

Object::Object(const Field& f) : json_(f.value), path_(f.path) {
  if (!json_.is_object()) fail(path_, "expected an object" + got(json_));
}

Field Object::operator[](const char* key) {
  const auto found = json_.find(key);
  if (found == json_.end()) fail(path_, std::string("missing field '") + key + "'");
  if (read_ < read_keys_.size()) read_keys_[read_] = key;
  ++read_;
  return {*found, path_.member(key)};
}

void Object::done() const {
  if (read_ == json_.size()) return;
  for (const auto& [key, value] : json_.items()) {
    bool known = false;
    for (std::size_t i = 0; i < read_ && i < read_keys_.size(); ++i) known |= key == read_keys_[i];
    if (!known) fail(path_, "unknown field '" + key + "'");
  }
}

std::string read_string(const Field& f) {
  if (!f.value.is_string()) fail(f.path, "expected a string" + got(f.value));
  return f.value.get<std::string>();
}

bool read_bool(const Field& f) {
  if (!f.value.is_boolean()) fail(f.path, "expected a boolean" + got(f.value));
  return f.value.get<bool>();
}

Index read_index(const Field& f) {
  if (f.value.is_null()) return kNone;
  const auto i = read_int<Index>(f);
  if (i == kNone) fail(f.path, "kNone is written null");
  return i;
}

double read_double(const Field& f) {
  if (f.value.is_number_float()) {
    const double d = f.value.get<double>();
    if (!std::isfinite(d)) fail(f.path, "a non-finite number must be written \"f64:...\"");
    return d;
  }
  if (!f.value.is_string()) fail(f.path, "expected a floating-point number" + got(f.value));
  const std::string& text = f.value.get_ref<const std::string&>();
  std::uint64_t bits = 0;
  const char* end = text.data() + text.size();
  if (text.size() != 20 || !text.starts_with("f64:") ||
      std::from_chars(text.data() + 4, end, bits, 16).ptr != end) {
    fail(f.path, "expected a floating-point number or \"f64:\" and 16 hex digits");
  }
  const double d = std::bit_cast<double>(bits);
  if (std::isfinite(d)) fail(f.path, "a finite number must be written as a number");
  return d;
}

const json& read_array(const Field& f, std::size_t size) {
  if (!f.value.is_array()) fail(f.path, "expected an array" + got(f.value));
  if (size != 0 && f.value.size() != size) {
    fail(f.path,
         "expected " + std::to_string(size) + " elements, got " + std::to_string(f.value.size()));
  }
  return f.value;
}

Location read_location(const Field& f) {
  read_array(f, 3);
  return {read_int<std::uint32_t>(element(f, 0)), read_int<std::uint32_t>(element(f, 1)),
          read_int<std::uint32_t>(element(f, 2))};
}

}  // namespace smcbip::bipc::ir::detail
