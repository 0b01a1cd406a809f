// The extern functions every engine provides without a definition from the model (C's printf,
// sleep, usleep, min, max, abs and rand): the engines register them, and generated code does
// not bind them to the model's own C++.
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

namespace smcbip::bipc::ir {

inline constexpr std::array<std::string_view, 7> kBuiltinFunctions = {
    "printf", "sleep", "usleep", "min", "max", "abs", "rand"};

inline bool is_builtin_function(std::string_view name) {
  return std::find(kBuiltinFunctions.begin(), kBuiltinFunctions.end(), name) !=
         kBuiltinFunctions.end();
}

}  // namespace smcbip::bipc::ir
