// Property files and JSON-lines traces driven from memory, for the fuzzers and their replay.
#pragma once

#include <cstddef>
#include <cstdint>

namespace smcbip::monitors::fuzz {

/// Parses `size` bytes as a property file, prints every declaration and query back as the tools
/// do, lists each query's bindings and resolves the names against models/channel.bip; must
/// never crash, hang or exhaust memory.
void run_properties_on(const std::uint8_t* data, std::size_t size);

/// Reads `size` bytes as a JSON-lines trace and judges it, in both readings of time, against
/// fixed properties over fired() and against properties over the first step's names; must
/// never crash or hang, and a bad trace must be a TraceError.
void run_trace_on(const std::uint8_t* data, std::size_t size);

}  // namespace smcbip::monitors::fuzz
