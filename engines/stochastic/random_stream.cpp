// The counter-based random stream of one run (see random_stream.h for the construction).
#include "engines/stochastic/random_stream.h"

#include <cstdio>
#include <cstdlib>

namespace smcbip::engines {

void RandomStream::below_zero() {
  std::fputs("smcbip: internal error: RandomStream::below(0)\n", stderr);
  std::abort();
}

}  // namespace smcbip::engines
