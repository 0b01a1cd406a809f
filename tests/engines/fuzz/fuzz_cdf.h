// The reader of empirical CDF files driven from memory, for the fuzzer and its regression replay.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smcbip::engines::fuzz {

/// Reads `size` bytes as an empirical CDF file (the `custom` distribution of @stochastic ports).
/// A refused file must get one message naming the file and, when a line is at fault, the line;
/// an accepted one must give a CDF in [0, 1] and an inverse within its values, both monotone,
/// and draws of the distribution; must never crash or hang.
void run_cdf_on(const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::engines::fuzz
