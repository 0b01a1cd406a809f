// The engine of each EngineKind.
#include "engines/engine.h"

#include "engines/multithread/multithread_engine.h"
#include "engines/optimised/optimised_engine.h"
#include "engines/reference/reference_engine.h"

namespace smcbip::engines {

const Engine& engine_of(EngineKind kind) {
  switch (kind) {
    case EngineKind::Optimised:
      return optimised_engine();
    case EngineKind::Multithread:
      return multithread_engine();
    case EngineKind::Reference:
      break;
  }
  return reference_engine();
}

}  // namespace smcbip::engines
