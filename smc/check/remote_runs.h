// Runs made by other processes (the ranks of an MPI job): the consumer hands them out in
// batches and takes their outcomes in run-index order, as OrderedSampler does with threads, so
// that the answers do not depend on how many processes made them.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "smc/check/query_runs.h"

namespace smcbip::smc {

class RemoteRuns {
 public:
  virtual ~RemoteRuns() = default;

  /// Whether this process makes runs for the consumer (a worker) rather than consuming them.
  virtual bool serving() const = 0;

  /// Consumer: hands out runs 0, 1, ... with the points' `done` flags as they stand, and gives
  /// their outcomes to `consume` in run order until it returns false. Returns "" or why a run
  /// could not be made, naming the process and the run.
  virtual std::string consume(std::size_t points, const std::atomic<bool>* done,
                              const std::function<bool(const RunOutcomes&)>& consume) = 0;

  /// Worker: makes the runs the consumer asks for with `produce`, after setting `done` as it
  /// sent them, until it says stop.
  virtual void serve(std::size_t points, std::atomic<bool>* done,
                     const std::function<void(std::uint64_t, RunOutcomes&)>& produce) = 0;
};

}  // namespace smcbip::smc
