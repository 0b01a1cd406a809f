// libFuzzer entry point over the parser and checker.
#include <cstddef>
#include <cstdint>

#include "fuzz_frontend.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::bipc::fuzz::run_frontend_on(data, size);
  return 0;
}
