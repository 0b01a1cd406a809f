// Simulates one model with the installed front end and engines, as `smcbip simulate` does.
#include "simulate_model.h"

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "bipc/bipc.h"
#include "bipc/options.h"
#include "engines/api/options.h"
#include "engines/engines.h"

int simulate_model(int argc, const char* const* argv) {
  using namespace smcbip;
  try {
    CLI::App app{"simulate a BIP model with the smcbip package"};
    bipc::FrontendOptions frontend;
    engines::SimulateOptions options;
    bipc::register_frontend_options(app, frontend);
    engines::register_simulate_options(app, options);
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      return app.exit(e) == 0 ? engines::kRunOk : engines::kUsageError;
    }
    bipc::FrontendResult result = bipc::run_frontend(frontend, /*need_system=*/true);
    std::cerr << result.diags.format(result.model.files);
    if (!result.system) return engines::kInputError;
    const engines::RunResult run =
        engines::simulate(*result.system, options, engines::Externs::with_builtins(), std::cout);
    std::cout.flush();
    return run.code;
  } catch (const std::exception& e) {
    std::cerr << "consumer: internal error: " << e.what() << "\n";
    return engines::kInternalError;
  }
}
