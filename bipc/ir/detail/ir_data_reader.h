// Internal interface of the IR data decoder: reading typed fields with their paths, and the
// reference check.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bipc/ir/detail/ir_data_names.h"
#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir::detail {

/// A field's place in the data: a chain of parent links, spelled out only when an error names
/// it, so that decoding a large model builds no strings.
struct Path {
  const Path* parent = nullptr;
  std::string_view key;  // an object member; unused for an array element
  std::size_t index = 0;
  bool element = false;

  Path member(std::string_view name) const { return {this, name, 0, false}; }
  Path item(std::size_t i) const { return {this, {}, i, true}; }
  /// `atom_types[2].transitions[0].guard`; "(top)" for the whole value.
  std::string text() const;
};

/// Throws IrDataError{"<path>: <what>"}.
[[noreturn]] void fail(const Path& path, const std::string& what);

/// A value and where it is.
struct Field {
  const nlohmann::json& value;
  Path path;
};

/// ", got <JSON type>", for messages.
std::string got(const nlohmann::json& value);

/// The members of one object: each read once, and none left unread at the end.
class Object {
 public:
  explicit Object(const Field& f);
  /// The member `key`; throws when it is missing.
  Field operator[](const char* key);
  /// Throws when the object has a member no one asked for.
  void done() const;

 private:
  const nlohmann::json& json_;
  Path path_;
  std::array<std::string_view, 24> read_keys_{};  // more than any struct of ir.h has fields
  std::size_t read_ = 0;
};

std::string read_string(const Field& f);
bool read_bool(const Field& f);
/// An unsigned index, or null for kNone (the number kNone itself is not a valid spelling).
Index read_index(const Field& f);
/// A finite JSON float, or "f64:" and the 16 hex digits of a non-finite double's bits.
double read_double(const Field& f);
/// The field as an array, of exactly `size` elements unless `size` is 0.
const nlohmann::json& read_array(const Field& f, std::size_t size = 0);
Location read_location(const Field& f);

/// An integer that fits `Int`.
template <typename Int>
Int read_int(const Field& f) {
  if (!f.value.is_number_integer()) fail(f.path, "expected an integer" + got(f.value));
  constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<Int>::max());
  if (f.value.is_number_unsigned()) {
    const auto u = f.value.get<std::uint64_t>();
    if (u > max) fail(f.path, std::to_string(u) + " out of range");
    return static_cast<Int>(u);
  }
  const auto i = f.value.get<std::int64_t>();
  if (i < static_cast<std::int64_t>(std::numeric_limits<Int>::min()) ||
      (i > 0 && static_cast<std::uint64_t>(i) > max)) {
    fail(f.path, std::to_string(i) + " out of range");
  }
  return static_cast<Int>(i);
}

/// The enumerator spelled by the field, one of `names`.
template <typename Enum, std::size_t N>
Enum read_enum(const Field& f, const std::array<const char*, N>& names) {
  const std::string text = read_string(f);
  const std::optional<Enum> value = enum_of<Enum>(names, text);
  if (!value) fail(f.path, "unknown name '" + text + "'");
  return *value;
}

/// The i-th element of an array already checked to have enough.
inline Field element(const Field& array, std::size_t i) {
  return {array.value[i], array.path.item(i)};
}

/// Each element of the array field read by `read_one(Field)`, in order.
template <typename ReadOne>
auto read_list(const Field& f, ReadOne read_one) {
  const nlohmann::json& array = read_array(f);
  std::vector<decltype(read_one(std::declval<Field>()))> out;
  out.reserve(array.size());
  for (std::size_t i = 0; i < array.size(); ++i) out.push_back(read_one(element(f, i)));
  return out;
}

/// Checks every index of a structurally decoded System against the tables it points into,
/// and the sizes instances must share with their types (the list in ir_data.h). Throws
/// IrDataError naming the first offending field.
void check_references(const System& system);

}  // namespace smcbip::bipc::ir::detail
