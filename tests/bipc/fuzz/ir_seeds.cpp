// Writes the IR data encodings of models as seeds for the IR decoder's fuzzer:
// `bipc_ir_seeds OUT_DIR FILE...` writes NAME.cbor and NAME.json for each model whose default
// root instantiates, and names on stderr those it skips.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

#include "bipc/bipc.h"
#include "bipc/ir/ir_data.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: bipc_ir_seeds OUT_DIR FILE...\n";
    return 1;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  int written = 0;
  for (int i = 2; i < argc; ++i) {
    smcbip::bipc::FrontendResult result = smcbip::bipc::run_frontend({argv[i], {}, ""}, true);
    if (!result.system) {
      std::cerr << "bipc_ir_seeds: skipped " << argv[i] << " (no default root)\n";
      continue;
    }
    const std::string name = std::filesystem::path(argv[i]).stem().string();
    const std::vector<std::uint8_t> bytes = smcbip::bipc::ir::to_bytes(*result.system);
    std::ofstream(out / (name + ".cbor"), std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    std::ofstream(out / (name + ".json")) << smcbip::bipc::ir::to_data(*result.system).dump();
    ++written;
  }
  std::cout << "bipc_ir_seeds: " << written << " models encoded\n";
  return 0;
}
