// libFuzzer entry point over the IR decoder (CBOR bytes and JSON text of ir_data.h).
#include <cstddef>
#include <cstdint>

#include "fuzz_ir_data.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  smcbip::bipc::fuzz::run_ir_data_on(data, size);
  return 0;
}
