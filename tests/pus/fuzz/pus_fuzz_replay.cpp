// Replays the PUS fuzzer's seeds and saved inputs as a plain test: `pus_fuzz_replay FILE...`.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "fuzz_decoder.h"

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << "pus_fuzz_replay: cannot open " << argv[i] << "\n";
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    smcbip::pus::fuzz::check_decoder(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                     bytes.size());
  }
  std::cout << "replayed " << (argc - 1) << " inputs\n";
  return 0;
}
