// The fdir library: invariant-based proofs of `A[] phi`, `A[] !deadlock` and `E<> phi` over BIP
// systems (D-Finder's method: component invariants, trap invariants of the Petri net, Z3), with
// counterexamples confirmed by the engines' exploration.
#pragma once

#include "fdir/errors.h"
#include "fdir/net/petri_net.h"
#include "fdir/prove/prover.h"
#include "fdir/search/counterexample_search.h"
