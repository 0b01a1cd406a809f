// The trace of one run, for comparing generated and interpreted models.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

#include "engines/engines.h"

namespace smcbip::tests {

/// The whole output of run 0 of `model` on `engine` with `seed`, at most `limit` steps, then
/// its exit code. The multithread engine uses two threads, firing atoms on them from
/// `parallel_min_work` instructions of work.
inline std::string run_trace(const engines::Model& model, engines::EngineKind engine,
                             std::uint64_t seed, std::uint64_t limit,
                             std::size_t parallel_min_work = 1000) {
  engines::SimulateOptions options;
  options.engine = engine;
  options.threads = 2;
  options.parallel_min_work = parallel_min_work;
  options.seed = seed;
  options.limit = limit;
  engines::Simulator simulator(model, options, engines::Externs::with_builtins());
  std::ostringstream out;
  const engines::RunResult result = simulator.run(0, engines::RunStreams{out, out});
  return out.str() + "\nexit " + std::to_string(result.code);
}

}  // namespace smcbip::tests
