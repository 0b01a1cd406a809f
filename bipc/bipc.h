// The bipc front end: load BIP2 packages, check them, and lower a root instantiation to the IR.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/ast/ast.h"
#include "bipc/diagnostics.h"
#include "bipc/ir/ir.h"

namespace smcbip::bipc {

/// The packages of a model: the one named on the command line and all it uses, transitively.
struct LoadedModel {
  SourceFiles files;
  std::vector<std::unique_ptr<ast::Package>> packages;  // dependencies before their users
  ast::Package* main = nullptr;                         // the package of the given file
};

/// Parses one package from text (no `use` resolution); appends syntax errors to `diags`.
std::unique_ptr<ast::Package> parse_package(const std::string& text, std::uint32_t file,
                                            Diagnostics& diags);

/// Whether `word` is a keyword of BIP2 (`end`, `port`, `data`, ...), which a name written into a
/// package must not be.
bool is_keyword(std::string_view word);

/// Parses a root instantiation such as `Syst()` or `pkg.Top(3, true)`.
std::optional<ast::ComponentDecl> parse_root(const std::string& text, std::uint32_t file,
                                             Diagnostics& diags);

/// Reads `path` and the packages it uses, found as `<dir>/<a>/<b>.bip` or `<dir>/<a.b>.bip` for
/// `use a.b`, in the file's own folder first, then in `search_dirs`. Returns the model even when
/// errors were found (as far as it could be read).
LoadedModel load(const std::string& path, const std::vector<std::string>& search_dirs,
                 Diagnostics& diags);

/// Checks every type of every loaded package and fills the AST's resolved fields.
/// Returns false when an error was found.
bool check(LoadedModel& model, Diagnostics& diags);

/// Resolves and checks a root instantiation against a checked model (parameters, arities).
bool check_root(const LoadedModel& model, ast::ComponentDecl& root, Diagnostics& diags);

/// Instantiates a checked root into the flattened IR; instance-level errors go to `diags`.
std::optional<ir::System> instantiate(const LoadedModel& model, const ast::ComponentDecl& root,
                                      Diagnostics& diags);

/// What a front-end run is asked to do: the file, its package search path, and the root.
struct FrontendOptions {
  std::string file;
  std::vector<std::string> include_dirs;
  std::string root;  // empty: check types only (or use default_root when `need_system`)
};

/// The result of a front-end run; `system` is set when a root was instantiated without errors.
struct FrontendResult {
  LoadedModel model;
  Diagnostics diags;
  std::optional<ir::System> system;
};

/// Loads, checks and, when a root is given (or `need_system` and a default root exists),
/// instantiates the model. Stops after the first stage that reports errors.
FrontendResult run_frontend(const FrontendOptions& options, bool need_system);

/// The root chosen when none is given: the single compound type of the main package that no
/// other type instantiates, if there is exactly one.
std::optional<std::string> default_root(const LoadedModel& model);

}  // namespace smcbip::bipc
