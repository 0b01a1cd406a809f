// The exception firewall every tool's main runs in: command-line errors, the user's errors and
// internal faults become one message on stderr and their documented exit code.
#pragma once

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "bipc/errors.h"
#include "bipc/exit_codes.h"

namespace smcbip::cli {

/// Parses the command line into `app`. --help and --version print and give 0; a bad command
/// line throws UsageError (the firewall reports it). Returns the exit code to leave with, or -1
/// to go on.
inline int parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    throw UsageError(std::string(e.what()) + "\nRun with --help for more information.");
  }
  return -1;
}

/// Runs `body` (returning the exit code) and turns whatever it throws into a message on stderr
/// prefixed by `tool` (or the error's location) and the exit code of `codes`.
template <typename Body>
int guarded_main(const std::string& tool, const exit_codes::FailureCodes& codes,
                 Body&& body) noexcept {
  try {
    try {
      return body();
    } catch (const UsageError& e) {
      std::cerr << e.describe(tool) << "\n";
      return codes.usage;
    } catch (const UserError& e) {
      std::cerr << e.describe(tool) << "\n";
      return codes.input;
    } catch (const std::bad_alloc&) {
      std::cerr << tool << ": internal error: out of memory\n";
    } catch (const std::exception& e) {
      std::cerr << tool << ": internal error: " << e.what() << "\n";
    } catch (...) {
      std::cerr << tool << ": internal error\n";
    }
  } catch (...) {  // writing the message failed: the code still says what happened
  }
  return codes.internal;
}

}  // namespace smcbip::cli
