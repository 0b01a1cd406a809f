// `smcbip check` and `explore` on the ranks of an MPI job, when smcbip is built with MPI.
#pragma once

#include "smc/tools/check_command.h"

namespace smcbip::tools {

/// Runs the command as run_check does; started by an MPI launcher with several ranks (and
/// built with MPI), rank 0 consumes the runs the other ranks make and alone reports.
int run_check_distributed(CheckCommand check, int& argc, char**& argv);

}  // namespace smcbip::tools
