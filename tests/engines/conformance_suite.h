// Checks shared by the files of the conformance suite (bip-conformance/EXPECTED.md sections 6, 8
// and 11, one file per section or theme, each a typed suite over AllEngines deriving from
// ConformanceFixture). Oracles that depend on the wall clock are in conformance_realtime_test.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>

#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {

/// True when the header of state `n` says one of `summaries`.
bool header_in(const Lines& lines, std::uint64_t n, std::initializer_list<const char*> summaries);

/// The exact --silent output of the tempcontrol models: the header line, then the rows of the
/// table of EXPECTED.md R02 (steps 1..3598).
Lines expected_tempcontrol_output();

/// The run ended normally and printed exactly the R02 table (shared by R02 and M05).
void expect_tempcontrol_table(const ConformanceRun& run);

/// Header n is `deadlock!`, and (the original check) one of the last k lines says so.
void expect_deadlock_in_tail(const Lines& lines, std::uint64_t n, std::size_t k);

}  // namespace smcbip::tests
