#include "engines/multithread/multithread_engine.h"

#include <algorithm>
#include <thread>

#include "engines/multithread/pool_firing.h"

namespace smcbip::engines {

namespace {

class MultithreadEngine final : public Engine {
 public:
  RuntimeOptions runtime_options(const SimulateOptions& options) const override {
    RuntimeOptions r = semantics_options(options);
    r.incremental = true;
    r.threads =
        options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    r.parallel_min_work = options.parallel_min_work;
    // One thread has no one to share the atoms with.
    if (r.threads > 1) r.parallel_firing = make_pool_firing;
    return r;
  }
  bool takes_compiled_steps() const override { return false; }
};

}  // namespace

const Engine& multithread_engine() {
  static const MultithreadEngine engine;
  return engine;
}

}  // namespace smcbip::engines
