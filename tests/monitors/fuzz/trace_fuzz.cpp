// libFuzzer entry point over the JSON-lines trace reader and the monitors it feeds.
#include <cstddef>
#include <cstdint>

#include "fuzz_monitors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::monitors::fuzz::run_trace_on(data, size);
  return 0;
}
