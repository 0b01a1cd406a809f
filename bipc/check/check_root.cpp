// The root instantiation: checking the one given on the command line, choosing one otherwise.
#include <algorithm>
#include <set>

#include "bipc/check/detail/check_compound.h"

namespace smcbip::bipc {

namespace {

void report_not_compound(const ast::ComponentDecl& root, const ast::Package& main,
                         const detail::Symbols& symbols, Diagnostics& diags) {
  const std::string name = root.type.text();
  const Location at = root.type.loc();
  if (symbols.atom_type(main, root.type) != nullptr) {
    diags.error(at, "root type '" + name + "' is an atom type: the root must be a compound type");
  } else if (symbols.connector_type(main, root.type) != nullptr ||
             symbols.port_type(main, root.type) != nullptr) {
    diags.error(at, "root type '" + name +
                        "' is not a component type: the root must be a "
                        "compound type");
  } else {
    diags.error(at, "unknown root type '" + name + "'");
  }
}

/// The packages of the model, the main one included even when the loader kept it apart.
std::vector<const ast::Package*> all_packages(const LoadedModel& model) {
  std::vector<const ast::Package*> packages;
  for (const auto& package : model.packages) packages.push_back(package.get());
  if (model.main != nullptr &&
      std::find(packages.begin(), packages.end(), model.main) == packages.end()) {
    packages.push_back(model.main);
  }
  return packages;
}

std::set<const ast::CompoundTypeDecl*> instantiated_by_others(const LoadedModel& model,
                                                              const detail::Symbols& symbols) {
  std::set<const ast::CompoundTypeDecl*> instantiated;
  for (const ast::Package* package : all_packages(model)) {
    for (const ast::CompoundTypeDecl& type : package->compound_types) {
      for (const ast::ComponentDecl& component : type.components) {
        const ast::CompoundTypeDecl* sub = component.compound_type;
        if (sub == nullptr && component.atom_type == nullptr && !component.type.parts.empty()) {
          sub = symbols.compound_type(*package, component.type);
        }
        if (sub != nullptr && sub != &type) instantiated.insert(sub);
      }
    }
  }
  return instantiated;
}

}  // namespace

bool check_root(const LoadedModel& model, ast::ComponentDecl& root, Diagnostics& diags) {
  const std::size_t errors_before = diags.error_count();
  if (model.main == nullptr || root.type.parts.empty()) {
    diags.error(root.loc, "no root type to instantiate");
    return false;
  }
  const detail::Symbols symbols(model);
  const ast::Package& main = *model.main;
  root.atom_type = nullptr;
  root.compound_type = symbols.compound_type(main, root.type);
  if (root.compound_type == nullptr) {
    report_not_compound(root, main, symbols, diags);
    return false;
  }
  const std::string what = "root type '" + root.type.text() + "'";
  if (detail::instantiation_never_ends(*root.compound_type, symbols)) {
    diags.error(root.type.loc(), what + " contains itself: its instantiation never ends");
  }
  // Root arguments are values known before any component exists: constants only.
  detail::ExprContext ctx;
  ctx.where = detail::ExprContext::Where::ConstInit;
  ctx.package = &main;
  detail::check_arguments(root.args, root.compound_type->params,
                          detail::owner_package(root.compound_type, main, symbols), ctx, what,
                          root.type.loc(), symbols, diags);
  return diags.error_count() == errors_before;
}

std::optional<std::string> default_root(const LoadedModel& model) {
  if (model.main == nullptr) return std::nullopt;
  const detail::Symbols symbols(model);
  const std::set<const ast::CompoundTypeDecl*> instantiated =
      instantiated_by_others(model, symbols);
  const ast::CompoundTypeDecl* candidate = nullptr;
  for (const ast::CompoundTypeDecl& type : model.main->compound_types) {
    if (instantiated.count(&type)) continue;
    if (candidate != nullptr) return std::nullopt;  // more than one: the user must choose
    candidate = &type;
  }
  if (candidate == nullptr || !candidate->params.empty()) return std::nullopt;
  return candidate->name.text + "()";
}

}  // namespace smcbip::bipc
