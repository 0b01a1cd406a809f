// JSON text for the tools' outputs (IR, reports, traces), whatever the bytes of its strings.
#pragma once

#include <string>

namespace smcbip::bipc {

/// `value` (an nlohmann::json or ordered_json) as text, indented by `indent` (-1: one line).
/// Strings need not be UTF-8 (a file name, an extern function's result may hold any bytes):
/// such bytes are written as U+FFFD rather than failing the output.
template <class Json>
std::string dump_json(const Json& value, int indent = -1) {
  return value.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace smcbip::bipc
