// models/channel.bip's system (root System()), loaded once for the monitors' tests.
#pragma once

#include <optional>
#include <string>

#include "tests/engines/temp_model.h"

namespace smcbip::monitors {

inline const bipc::ir::System& channel() {
  static const std::optional<bipc::ir::System> system =
      tests::load_model(std::string(SMCBIP_SOURCE_DIR) + "/models/channel.bip", "System()");
  return *system;
}

}  // namespace smcbip::monitors
