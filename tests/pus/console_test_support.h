// Values the console's tests build.
#pragma once

#include <cstdint>

#include "console/console.h"

namespace smcbip::pus::console::testing {

/// An ST01 report of `request`, with a step ID and a failure code.
inline Verification verification(const RequestId& request, std::uint64_t step = 0,
                                 std::uint64_t code = 0) {
  Verification v;
  v.request = request;
  v.step_id = step;
  v.failure_code = code;
  return v;
}

}  // namespace smcbip::pus::console::testing
