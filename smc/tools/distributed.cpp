#include "smc/tools/distributed.h"

#include <iostream>
#include <streambuf>

#ifdef SMCBIP_WITH_MPI
#include "smc/mpi/mpi_runs.h"
#endif

namespace smcbip::tools {

#ifdef SMCBIP_WITH_MPI
namespace {

/// Where a worker rank's messages go: rank 0 reports the same ones.
class Silence final : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

}  // namespace

int run_check_distributed(CheckCommand check, int& argc, char**& argv) {
  if (!smc::mpi::launched_with_ranks()) return run_check(std::move(check));
  const smc::mpi::Session session(argc, argv);
  smc::mpi::MpiRuns runs(session);
  check.remote = &runs;
  check.worker = session.rank() != 0;
  Silence silence;
  std::streambuf* out = std::cout.rdbuf();
  std::streambuf* err = std::cerr.rdbuf();
  if (check.worker) {
    std::cout.rdbuf(&silence);
    std::cerr.rdbuf(&silence);
  }
  const int code = run_check(std::move(check));
  std::cout.rdbuf(out);
  std::cerr.rdbuf(err);
  return code;
}

#else

int run_check_distributed(CheckCommand check, int&, char**&) { return run_check(std::move(check)); }

#endif

}  // namespace smcbip::tools
