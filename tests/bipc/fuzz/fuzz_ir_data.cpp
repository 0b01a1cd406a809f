// The IR decoder driven from memory, for the fuzzer and its regression replay.
#include "fuzz_ir_data.h"

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "bipc/ir/ir_data.h"
#include "bipc/ir/ir_json.h"
#include "bipc/ir/ir_text.h"

namespace smcbip::bipc::fuzz {

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "%s: %s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

void run_ir_data_on(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  std::optional<ir::System> system;
  try {
    if (first != std::string_view::npos && text[first] == '{') {
      const nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
      if (value.is_discarded()) return;
      system = ir::from_data(value);
    } else {
      system = ir::from_bytes(std::span<const std::uint8_t>(data, size));
    }
  } catch (const ir::IrDataError& e) {
    return;
  }
  const std::vector<std::uint8_t> bytes = ir::to_bytes(*system);
  try {
    if (ir::to_bytes(ir::from_bytes(bytes)) != bytes) {
      broken("decoded IR", "encodes to other bytes after a round trip");
    }
  } catch (const ir::IrDataError& e) {
    broken("the encoding of a decoded IR is refused", e.message);
  }
  (void)ir::to_text(*system);
  (void)ir::to_json(*system);
}

}  // namespace smcbip::bipc::fuzz
