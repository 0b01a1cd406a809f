// Replays saved inputs of the empirical CDF fuzzer (crashers that were fixed, and the seeds) as
// plain tests.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "fuzz_cdf.h"

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << "cdf_fuzz_replay: cannot open " << argv[i] << "\n";
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    smcbip::engines::fuzz::run_cdf_on(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                      bytes.size());
  }
  std::cout << "replayed " << (argc - 1) << " inputs\n";
  return 0;
}
