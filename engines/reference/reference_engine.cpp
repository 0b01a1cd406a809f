#include "engines/reference/reference_engine.h"

namespace smcbip::engines {

namespace {

class ReferenceEngine final : public Engine {
 public:
  RuntimeOptions runtime_options(const SimulateOptions& options) const override {
    return semantics_options(options);
  }
  bool takes_compiled_steps() const override { return false; }
};

}  // namespace

const Engine& reference_engine() {
  static const ReferenceEngine engine;
  return engine;
}

}  // namespace smcbip::engines
