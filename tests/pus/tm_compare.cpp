// pus_tm_compare: compares two runs' TM packets (hex, one a line), e.g. the model simulated
// and the deployed program, apart from what only says when, and how often, they were made.
//
// Each packet is decoded by the packet library (a refused one fails the comparison, which also
// checks its CRC) and its sequence counts must follow one another in its run (no packet lost).
// Then masked, as they depend on the moment or on how many periodic reports came before: the
// CUC times (tm_time_fields: the secondary header's and [9,2]'s), the sequence count, the CRC
// (over both), and for the periodic types (--count) the message type counter too. The other
// packets must then be equal octet for octet and in the same order; each periodic type's
// packets equal to one another across both runs, and their count in each run within MIN..MAX
// (real time decides how many fall in a window the TCs open and close).
//
// Usage: pus_tm_compare EXPECTED ACTUAL [--count SERVICE,SUBTYPE=MIN..MAX]...
// Exit codes: 0 the same, 1 they differ, 2 usage or unreadable input.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "console/hex.h"
#include "packets/packets.h"

namespace {

using namespace smcbip::pus;
using Type = std::pair<unsigned, unsigned>;

struct Range {
  unsigned min = 0, max = 0;
};

struct Run {
  std::vector<std::string> others;                    ///< masked hex, in order
  std::map<Type, std::vector<std::string>> periodic;  ///< masked hex per periodic type
};

constexpr std::size_t kSequenceCountOffset = 2;
constexpr std::size_t kMessageCounterOffset = kPrimaryHeaderLength + 3;

bool read_run(const std::string& path, const std::map<Type, Range>& counts, Run& run) {
  std::ifstream file(path);
  if (!file) {
    std::cerr << path << ": cannot read this file\n";
    return false;
  }
  const Config config{};
  std::string line;
  std::optional<std::uint16_t> last_count;
  for (std::uint32_t number = 1; std::getline(file, line); ++number) {
    std::vector<std::uint8_t> bytes;
    smcbip::pus::console::HexError error;
    if (!smcbip::pus::console::parse_hex(line, bytes, error)) {
      std::cerr << path << ":" << number << ": expected " << error.expected << "\n";
      return false;
    }
    auto tm = decode_tm(bytes, config);
    if (!tm) {
      std::cerr << path << ":" << number << ": not a valid TM: " << tm.error().message << "\n";
      return false;
    }
    const std::uint16_t count = tm.value().primary.sequence_count;
    if (last_count && count != ((*last_count + 1) & 0x3FFF)) {
      std::cerr << path << ":" << number << ": sequence count " << count << " after " << *last_count
                << ": a packet was lost\n";
      return false;
    }
    last_count = count;
    for (const FieldSpan& field : tm_time_fields(tm.value(), config)) {
      std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(field.offset), field.length, 0);
    }
    bytes[kSequenceCountOffset] &= 0xC0;  // the sequence flags stay
    bytes[kSequenceCountOffset + 1] = 0;
    bytes[bytes.size() - 2] = bytes[bytes.size() - 1] = 0;
    const Type type{tm.value().header.service, tm.value().header.subtype};
    if (counts.contains(type)) {
      bytes[kMessageCounterOffset] = bytes[kMessageCounterOffset + 1] = 0;
      run.periodic[type].push_back(smcbip::pus::console::to_hex(bytes));
    } else {
      run.others.push_back(smcbip::pus::console::to_hex(bytes));
    }
  }
  return true;
}

bool same_others(const Run& expected, const Run& actual) {
  for (std::size_t i = 0; i < std::max(expected.others.size(), actual.others.size()); ++i) {
    const std::string e = i < expected.others.size() ? expected.others[i] : "(none)";
    const std::string a = i < actual.others.size() ? actual.others[i] : "(none)";
    if (e != a) {
      std::cerr << "non-periodic packet " << i + 1 << " differs (masked):\n  expected " << e
                << "\n  actual   " << a << "\n";
      return false;
    }
  }
  return true;
}

bool same_periodic(const Run& expected, const Run& actual, const std::map<Type, Range>& counts) {
  bool same = true;
  for (const auto& [type, range] : counts) {
    const auto take = [&](const Run& run) {
      const auto found = run.periodic.find(type);
      return found == run.periodic.end() ? std::vector<std::string>{} : found->second;
    };
    const std::vector<std::string> e = take(expected), a = take(actual);
    std::set<std::string> distinct(e.begin(), e.end());
    distinct.insert(a.begin(), a.end());
    const std::string name =
        "TM[" + std::to_string(type.first) + "," + std::to_string(type.second) + "]";
    if (distinct.size() > 1) {
      std::cerr << name << " reports differ (masked):";
      for (const std::string& hex : distinct) std::cerr << "\n  " << hex;
      std::cerr << "\n";
      same = false;
    }
    for (const auto& [run, size] :
         {std::pair{"expected", e.size()}, std::pair{"actual", a.size()}}) {
      if (size < range.min || size > range.max) {
        std::cerr << name << ": " << size << " in the " << run << " run, not within " << range.min
                  << ".." << range.max << "\n";
        same = false;
      }
    }
  }
  return same;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  std::map<Type, Range> counts;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    unsigned service = 0, subtype = 0;
    Range range;
    if (arg == "--count" && i + 1 < argc &&
        std::sscanf(argv[i + 1], "%u,%u=%u..%u", &service, &subtype, &range.min, &range.max) == 4) {
      counts[{service, subtype}] = range;
      ++i;
    } else if (arg.starts_with("-")) {
      std::cerr << "usage: pus_tm_compare EXPECTED ACTUAL [--count SVC,SUB=MIN..MAX]...\n";
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.size() != 2) {
    std::cerr << "usage: pus_tm_compare EXPECTED ACTUAL [--count SVC,SUB=MIN..MAX]...\n";
    return 2;
  }
  Run expected, actual;
  if (!read_run(files[0], counts, expected) || !read_run(files[1], counts, actual)) return 2;
  const bool others = same_others(expected, actual);
  const bool periodic = same_periodic(expected, actual, counts);
  if (!others || !periodic) return 1;
  std::cout << "pus_tm_compare: " << expected.others.size() << " packets equal in order";
  for (const auto& [type, packets] : actual.periodic) {
    std::cout << "; TM[" << type.first << "," << type.second << "] x"
              << expected.periodic[type].size() << " / x" << packets.size();
  }
  std::cout << "\n";
  return 0;
}
