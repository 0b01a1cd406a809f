// The consumer program: `consumer [--plugin MODULE] FILE --root R --seed S --limit N` simulates
// the model itself, or through the module's entry point (as smcbip will load model plugins).
#include <dlfcn.h>

#include <iostream>
#include <string_view>

#include "simulate_model.h"

namespace {

using EntryPoint = int (*)(int, const char* const*);

int run_plugin(const char* path, int argc, const char* const* argv) {
  void* module = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) {
    std::cerr << "consumer: cannot load " << path << ": " << dlerror() << "\n";
    return 70;
  }
  auto entry = reinterpret_cast<EntryPoint>(dlsym(module, "consumer_plugin_simulate"));
  if (entry == nullptr) {
    std::cerr << "consumer: " << path << " has no consumer_plugin_simulate\n";
    return 70;
  }
  const int code = entry(argc, argv);
  dlclose(module);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && std::string_view(argv[1]) == "--plugin") {
    // The module parses the rest of the command line as its own (argv[2] stands for argv[0]).
    return run_plugin(argv[2], argc - 2, argv + 2);
  }
  return simulate_model(argc, argv);
}
