#include "engines/optimised/optimised_engine.h"

namespace smcbip::engines {

namespace {

class OptimisedEngine final : public Engine {
 public:
  RuntimeOptions runtime_options(const SimulateOptions& options) const override {
    RuntimeOptions r = semantics_options(options);
    r.incremental = true;
    return r;
  }
  bool takes_compiled_steps() const override { return true; }
};

}  // namespace

const Engine& optimised_engine() {
  static const OptimisedEngine engine;
  return engine;
}

}  // namespace smcbip::engines
