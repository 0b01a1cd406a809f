// libFuzzer entry point over the sdl reader of taste2bip.
#include <cstddef>
#include <cstdint>

#include "fuzz_taste.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::taste2bip::fuzz::run_reader_on(smcbip::taste2bip::fuzz::Reader::Sdl, data, size);
  return 0;
}
