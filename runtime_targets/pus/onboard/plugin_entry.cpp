// The entry point smcbip finds when it loads pus_onboard's plugin (--compiled), as bipc gen
// writes it for its own projects (the generated plugin.cpp is not among smcbip_add_model's
// outputs, so the build names its own).
#include "engines/api/plugin.h"
#include "model.h"

extern "C" __attribute__((visibility("default"))) const smcbip::engines::PluginEntry*
smcbip_model_plugin() {
  static const smcbip::engines::PluginEntry entry{smcbip::engines::kPluginAbi,
                                                  smcbip::engines::plugin_layout(),
                                                  pus_onboard::kModelHash.data(),
                                                  pus_onboard::kRoot.data(),
                                                  &pus_onboard::model,
                                                  &pus_onboard::register_externs};
  return &entry;
}
