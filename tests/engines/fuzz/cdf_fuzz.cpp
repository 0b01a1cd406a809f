// libFuzzer entry point over the reader of empirical CDF files (@stochastic dist=custom).
#include <cstddef>
#include <cstdint>

#include "fuzz_cdf.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::engines::fuzz::run_cdf_on(data, size);
  return 0;
}
