// One silent run of a loaded model by one engine, for tests that look at how it ends.
#pragma once

#include <cstdint>
#include <sstream>

#include "engines/engines.h"

namespace smcbip::tests {

/// The run of `system` by `engine` (the multithread one on 2 threads) with `seed`, cut after
/// `limit` steps.
inline engines::RunResult run_once(const bipc::ir::System& system, engines::EngineKind engine,
                                   std::uint64_t seed, std::uint64_t limit) {
  engines::SimulateOptions options;
  options.engine = engine;
  options.threads = 2;
  options.seed = seed;
  options.limit = limit;
  std::ostringstream out;
  return engines::simulate(system, options, engines::Externs::with_builtins(), out);
}

}  // namespace smcbip::tests
