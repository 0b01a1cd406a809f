// Command-line options of the front end, declared once and shared by every tool that reads models.
#pragma once

#include <CLI/CLI.hpp>

#include "bipc/bipc.h"

namespace smcbip::bipc {

/// Registers FILE (required unless `file_required` is false), -I/--include and --root on a
/// (sub)command.
inline void register_frontend_options(CLI::App& app, FrontendOptions& options,
                                      bool file_required = true) {
  app.add_option("file", options.file, "BIP2 package file (.bip)")->required(file_required);
  app.add_option("-I,--include", options.include_dirs,
                 "folder searched for used packages (repeatable)");
  app.add_option("--root", options.root, "root instantiation, e.g. 'Syst()' or 'pkg.Top(3)'");
}

}  // namespace smcbip::bipc
