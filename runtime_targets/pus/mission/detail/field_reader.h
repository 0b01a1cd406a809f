// Typed reads of JSON members with located errors, shared by the sections of the mission.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "detail/located_json.h"
#include "mission.h"

namespace smcbip::pus::mission::detail {

/// Reads members of objects of a located document, collecting a located error for every
/// missing, mistyped or out-of-range member; a read that fails returns nothing.
class FieldReader {
 public:
  FieldReader(std::string_view text, const LocatedJson& doc) : text_(text), doc_(doc) {}

  /// Records an error located at the key (or value) of `pointer`.
  void error(const std::string& pointer, std::string message);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  bool failed() const { return !diagnostics_.empty(); }

  /// The value at `pointer` (nullptr if absent).
  const nlohmann::json* at(const std::string& pointer) const;
  /// Refuses any key of the object at `pointer` not in `known` (a misspelt key would be
  /// silently ignored otherwise); false if the value is not an object.
  bool object_with(const std::string& pointer, std::initializer_list<std::string_view> known);
  /// The elements of the array member `key` of `object` (absent: empty if optional).
  std::optional<std::size_t> array_size(const std::string& object, std::string_view key,
                                        bool required);

  /// An unsigned integer fitting `bytes` octets (or the given maximum).
  std::optional<std::uint64_t> id(const std::string& object, std::string_view key,
                                  std::uint8_t bytes);
  std::optional<std::uint64_t> unsigned_in(const std::string& object, std::string_view key,
                                           std::uint64_t min, std::uint64_t max);
  std::optional<double> number(const std::string& object, std::string_view key);
  std::optional<std::string> string(const std::string& object, std::string_view key);
  std::optional<bool> boolean(const std::string& object, std::string_view key);
  std::optional<ValueType> value_type(const std::string& object, std::string_view key);
  std::optional<Severity> severity(const std::string& object, std::string_view key);

  /// `object` + "/" + key.
  static std::string member(const std::string& object, std::string_view key);
  static std::string element(const std::string& array, std::size_t index);

 private:
  const nlohmann::json* required(const std::string& object, std::string_view key);

  std::string_view text_;
  const LocatedJson& doc_;
  std::vector<Diagnostic> diagnostics_;
};

/// The largest value of an unsigned field of `bytes` octets.
std::uint64_t max_of_width(std::uint8_t bytes);

}  // namespace smcbip::pus::mission::detail
