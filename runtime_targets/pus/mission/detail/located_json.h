// JSON parsed with the offset of every value and key, so that semantic errors can be located.
#pragma once

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <variant>

namespace smcbip::pus::mission::detail {

/// A JSON document and, for each JSON pointer (RFC 6901), the byte offset where its value
/// starts and, for object members, where its key starts.
struct LocatedJson {
  nlohmann::json value;
  std::map<std::string, std::size_t> value_offsets;
  std::map<std::string, std::size_t> key_offsets;

  /// Where to point for an error about `pointer`: its key if it has one, else its value, else
  /// the nearest enclosing value that has an offset.
  std::size_t offset_of(const std::string& pointer) const;
};

/// Why the text is not JSON: nlohmann's message and the byte offset of the offending token.
struct JsonSyntaxError {
  std::size_t offset = 0;
  std::string message;
};

/// Parses JSON text (duplicate keys refused: the later one would silently win).
std::variant<LocatedJson, JsonSyntaxError> parse_located(std::string_view text);

/// 1-based line and column (in bytes) of an offset.
std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t offset);

/// The JSON pointer escape of one reference token ("~" -> "~0", "/" -> "~1").
std::string escape_pointer_token(std::string_view token);

}  // namespace smcbip::pus::mission::detail
