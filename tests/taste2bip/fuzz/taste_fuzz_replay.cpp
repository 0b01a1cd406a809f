// Replays saved inputs of the taste2bip fuzzers as plain tests: `taste_fuzz_replay READER FILE...`
// with READER one of asn1, aadl, xml, sdl.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "fuzz_taste.h"

int main(int argc, char** argv) {
  using smcbip::taste2bip::fuzz::Reader;
  Reader reader{};
  if (argc < 2 || !smcbip::taste2bip::fuzz::reader_named(argv[1], reader)) {
    std::cerr << "usage: taste_fuzz_replay asn1|aadl|xml|sdl|sdlatom FILE...\n";
    return 2;
  }
  for (int i = 2; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << "taste_fuzz_replay: cannot open " << argv[i] << "\n";
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    smcbip::taste2bip::fuzz::run_reader_on(
        reader, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << "replayed " << (argc - 2) << " inputs\n";
  return 0;
}
