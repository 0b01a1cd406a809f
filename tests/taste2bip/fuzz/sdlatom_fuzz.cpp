// libFuzzer entry point over the SDL translation of taste2bip (read, translate, check).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_taste.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::taste2bip::fuzz::translate_sdl_on(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
