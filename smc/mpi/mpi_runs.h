// smcbip on an MPI job: rank 0 consumes the runs that the other ranks make (RemoteRuns), in
// run-index order, so that any number of ranks gives the answers of one process.
#pragma once

#include <cstdint>
#include <vector>

#include "smc/check/remote_runs.h"

namespace smcbip::smc::mpi {

/// Whether this process was started by an MPI launcher (mpirun, srun) with more than one rank.
bool launched_with_ranks();

/// MPI for the life of the object: initialised, then finalised. When the launcher ends the job
/// early (SIGTERM, SIGINT: a rank failed, or the job was stopped), rank 0 stops waiting for
/// runs, reports what it has and exits with kEnded instead of finalising.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  static constexpr int kEnded = 2;

  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

/// Rank 0 hands out batches of runs to the other ranks, `ahead` batches each at most, and takes
/// their outcomes in order; the others serve them.
class MpiRuns final : public RemoteRuns {
 public:
  explicit MpiRuns(const Session& session, std::uint64_t batch = 16, unsigned ahead = 2)
      : rank_(session.rank()), size_(session.size()), batch_(batch), ahead_(ahead) {}

  bool serving() const override { return rank_ != 0; }
  std::string consume(std::size_t points, const std::atomic<bool>* done,
                      const std::function<bool(const RunOutcomes&)>& consume) override;
  void serve(std::size_t points, std::atomic<bool>* done,
             const std::function<void(std::uint64_t, RunOutcomes&)>& produce) override;

 private:
  int rank_, size_;
  std::uint64_t batch_;
  unsigned ahead_;
  bool ended_ = false;
};

}  // namespace smcbip::smc::mpi
