// random_bip_model: prints one random BIP2 package (root `Root()`) to reproduce a failing seed.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <iostream>
#include <string>

#include "random_model.h"

namespace {

/// Exit codes, as for every smcbip tool: 0 success, 2 usage error, 3 internal error.
constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

}  // namespace

int main(int argc, char** argv) {
  try {
    smcbip::tests::RandomModelOptions options;
    std::string package = "random_model";
    bool no_priorities = false, no_data = false, no_hierarchy = false;
    CLI::App app{"Prints a random valid BIP2 package whose root is Root() (see random_model.h)."};
    app.add_option("seed", options.seed, "seed of the generator")->required();
    app.add_option("--atoms", options.atoms, "atom instances")
        ->capture_default_str()
        ->check(CLI::Range(1, 10'000));
    app.add_option("--places", options.max_places, "most places of an atom's main token")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    app.add_option("--ports", options.max_ports, "most exported ports per atom type")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    app.add_option("--connectors", options.connectors, "connectors of the root compound")
        ->capture_default_str()
        ->check(CLI::Range(0, 10'000));
    app.add_flag("--clocks", options.clocks, "timed model: clocks, clock guards, urgencies");
    app.add_flag("--no-priorities", no_priorities, "no priority rules");
    app.add_flag("--no-data", no_data, "no data, guards or actions");
    app.add_flag("--no-hierarchy", no_hierarchy, "no sub-compounds nor hierarchical connectors");
    app.add_flag("--rendezvous", options.rendezvous_only, "every connector a rendezvous");
    app.add_flag("--stochastic", options.stochastic,
                 "@stochastic ports on timed atoms (with --clocks)");
    app.add_option("--package", package, "package name")->capture_default_str();
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
      const int code = app.exit(error);
      return code == 0 ? kExitOk : kExitUsage;
    }
    options.priorities = !no_priorities;
    options.data = !no_data;
    options.hierarchy = !no_hierarchy;
    std::cout << smcbip::tests::random_bip_package(options, package);
    std::cout.flush();
    return std::cout ? kExitOk : kExitInternal;
  } catch (const std::exception& error) {
    std::cerr << "random_bip_model: internal error: " << error.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "random_bip_model: internal error\n";
    return kExitInternal;
  }
}
