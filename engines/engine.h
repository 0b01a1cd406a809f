// The engines as modules: engines/reference, engines/optimised and engines/multithread, each
// saying what it adds to the semantics that all of them share (engines/semantics/). They agree
// on every run: same steps, same laws, same errors (tests/engines/cross_engine_test.cpp).
#pragma once

#include "engines/api/simulate.h"
#include "engines/semantics/runtime_types.h"

namespace smcbip::engines {

class Engine {
 public:
  virtual ~Engine() = default;
  /// The Runtime's options for runs with `options`: whether each connector's interactions are
  /// kept between steps (the incremental cache) and how an interaction's atoms fire (in
  /// sequence, or by a parallel firing).
  virtual RuntimeOptions runtime_options(const SimulateOptions& options) const = 0;
  /// How the next item is chosen: whether runs take the model's compiled step path (flat
  /// tables and a chooser of their own, the same law) when they can, or decide every step
  /// through the Scheduler.
  virtual bool takes_compiled_steps() const = 0;
};

/// What every engine's RuntimeOptions start from: the options of the semantics itself.
inline RuntimeOptions semantics_options(const SimulateOptions& options) {
  RuntimeOptions r;
  r.maximal_progress = !options.disable_maximal_progress;
  return r;
}

/// The engine `--engine` names.
const Engine& engine_of(EngineKind kind);

}  // namespace smcbip::engines
