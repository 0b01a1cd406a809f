// libFuzzer entry point over the property language: parser, printer, name resolution.
#include <cstddef>
#include <cstdint>

#include "fuzz_monitors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::monitors::fuzz::run_properties_on(data, size);
  return 0;
}
