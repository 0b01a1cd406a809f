// Typed, located reads of the members of a mission configuration.
#include "detail/field_reader.h"

#include <array>
#include <cmath>

namespace smcbip::pus::mission::detail {

using nlohmann::json;

std::uint64_t max_of_width(std::uint8_t bytes) {
  return bytes >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * bytes)) - 1;
}

std::string FieldReader::member(const std::string& object, std::string_view key) {
  return object + "/" + escape_pointer_token(key);
}

std::string FieldReader::element(const std::string& array, std::size_t index) {
  return array + "/" + std::to_string(index);
}

void FieldReader::error(const std::string& pointer, std::string message) {
  const auto [line, column] = line_column(text_, doc_.offset_of(pointer));
  diagnostics_.push_back(Diagnostic{line, column, std::move(message)});
}

const json* FieldReader::at(const std::string& pointer) const {
  const json::json_pointer ptr(pointer);
  return doc_.value.contains(ptr) ? &doc_.value.at(ptr) : nullptr;
}

bool FieldReader::object_with(const std::string& pointer,
                              std::initializer_list<std::string_view> known) {
  const json* value = at(pointer);
  if (value == nullptr || !value->is_object()) {
    error(pointer, "expected an object");
    return false;
  }
  for (const auto& item : value->items()) {
    bool found = false;
    for (const std::string_view k : known) found = found || k == item.key();
    if (!found) error(member(pointer, item.key()), "unknown key \"" + item.key() + "\"");
  }
  return true;
}

const json* FieldReader::required(const std::string& object, std::string_view key) {
  const json* value = at(member(object, key));
  if (value == nullptr) error(object, "missing \"" + std::string(key) + "\"");
  return value;
}

std::optional<std::size_t> FieldReader::array_size(const std::string& object, std::string_view key,
                                                   bool required_member) {
  const json* value = at(member(object, key));
  if (value == nullptr) {
    if (!required_member) return std::size_t{0};
    error(object, "missing \"" + std::string(key) + "\"");
    return std::nullopt;
  }
  if (!value->is_array()) {
    error(member(object, key), "\"" + std::string(key) + "\" must be an array");
    return std::nullopt;
  }
  return value->size();
}

std::optional<std::uint64_t> FieldReader::unsigned_in(const std::string& object,
                                                      std::string_view key, std::uint64_t min,
                                                      std::uint64_t max) {
  const json* value = required(object, key);
  if (value == nullptr) return std::nullopt;
  const bool is_unsigned = value->is_number_unsigned() ||
                           (value->is_number_integer() && value->get<std::int64_t>() >= 0);
  if (!is_unsigned || value->get<std::uint64_t>() < min || value->get<std::uint64_t>() > max) {
    error(member(object, key), "\"" + std::string(key) + "\" must be an integer in " +
                                   std::to_string(min) + ".." + std::to_string(max));
    return std::nullopt;
  }
  return value->get<std::uint64_t>();
}

std::optional<std::uint64_t> FieldReader::id(const std::string& object, std::string_view key,
                                             std::uint8_t bytes) {
  return unsigned_in(object, key, 0, max_of_width(bytes));
}

std::optional<double> FieldReader::number(const std::string& object, std::string_view key) {
  const json* value = required(object, key);
  if (value == nullptr) return std::nullopt;
  if (!value->is_number()) {
    error(member(object, key), "\"" + std::string(key) + "\" must be a number");
    return std::nullopt;
  }
  return value->get<double>();
}

std::optional<std::string> FieldReader::string(const std::string& object, std::string_view key) {
  const json* value = required(object, key);
  if (value == nullptr) return std::nullopt;
  if (!value->is_string()) {
    error(member(object, key), "\"" + std::string(key) + "\" must be a string");
    return std::nullopt;
  }
  return value->get<std::string>();
}

std::optional<bool> FieldReader::boolean(const std::string& object, std::string_view key) {
  const json* value = required(object, key);
  if (value == nullptr) return std::nullopt;
  if (!value->is_boolean()) {
    error(member(object, key), "\"" + std::string(key) + "\" must be true or false");
    return std::nullopt;
  }
  return value->get<bool>();
}

std::optional<ValueType> FieldReader::value_type(const std::string& object, std::string_view key) {
  const auto name = string(object, key);
  if (!name) return std::nullopt;
  for (const ValueType type :
       {ValueType::Uint32, ValueType::Int32, ValueType::Float32, ValueType::Bool}) {
    if (*name == type_name(type)) return type;
  }
  error(member(object, key), "unknown type \"" + *name + "\" (uint32, int32, float32, bool)");
  return std::nullopt;
}

std::optional<Severity> FieldReader::severity(const std::string& object, std::string_view key) {
  static constexpr std::array<std::string_view, 4> kNames{"informative", "low", "medium", "high"};
  const auto name = string(object, key);
  if (!name) return std::nullopt;
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (*name == kNames[i]) return static_cast<Severity>(i);
  }
  error(member(object, key), "unknown severity \"" + *name + "\" (informative, low, medium, high)");
  return std::nullopt;
}

}  // namespace smcbip::pus::mission::detail
