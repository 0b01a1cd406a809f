// The consumer's shared module: the engines linked in, one C entry point exported.
#include "simulate_model.h"

/// Simulates as `consumer` does; looked up with dlsym by `consumer --plugin`.
extern "C" __attribute__((visibility("default"))) int consumer_plugin_simulate(
    int argc, const char* const* argv) {
  return simulate_model(argc, argv);
}
