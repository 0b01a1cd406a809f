// One fuzz input through the whole front end: parse, check, instantiate the default root.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smcbip::bipc::fuzz {

/// Runs the front end on `size` bytes of model text held in memory; must never crash or hang.
void run_frontend_on(const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::bipc::fuzz
