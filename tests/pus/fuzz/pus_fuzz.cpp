// libFuzzer entry point over the PUS packet decoder.
#include <cstddef>
#include <cstdint>

#include "fuzz_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::pus::fuzz::check_decoder(data, size);
  return 0;
}
