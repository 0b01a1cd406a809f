// Replays saved fuzzer inputs (crashers that were fixed, and the seeds) as plain tests:
// `monitors_fuzz_replay property|trace FILE...`.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_monitors.h"

int main(int argc, char** argv) {
  if (argc < 2 || (std::strcmp(argv[1], "property") != 0 && std::strcmp(argv[1], "trace") != 0)) {
    std::cerr << "usage: monitors_fuzz_replay property|trace FILE...\n";
    return 1;
  }
  const bool property = std::strcmp(argv[1], "property") == 0;
  for (int i = 2; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::cerr << "fuzz_replay: cannot open " << argv[i] << "\n";
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (property) {
      smcbip::monitors::fuzz::run_properties_on(data, bytes.size());
    } else {
      smcbip::monitors::fuzz::run_trace_on(data, bytes.size());
    }
  }
  std::cout << "replayed " << (argc - 2) << " inputs\n";
  return 0;
}
