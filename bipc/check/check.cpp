// The checker's entry point: every package, dependencies first, then each of its types.
#include "bipc/bipc.h"
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc {

namespace detail {

namespace {

template <typename Decl>
void add_names(std::vector<const ast::Ident*>& names, const std::vector<Decl>& decls) {
  for (const Decl& decl : decls) names.push_back(&decl.name);
}

/// Port, atom, connector and compound types share one namespace; constants and extern data
/// types have one each.
void declare_package_names(const ast::Package& package, Diagnostics& diags) {
  std::vector<const ast::Ident*> types;
  add_names(types, package.port_types);
  add_names(types, package.atom_types);
  add_names(types, package.connector_types);
  add_names(types, package.compound_types);
  declare_in_source_order(types, diags);
  std::vector<const ast::Ident*> constants;
  add_names(constants, package.consts);
  declare_in_source_order(constants, diags);
  std::vector<const ast::Ident*> extern_types;
  add_names(extern_types, package.extern_types);
  declare_in_source_order(extern_types, diags);
}

void check_package(ast::Package& package, const Symbols& symbols, Diagnostics& diags) {
  declare_package_names(package, diags);
  check_annotation_redefinitions(package, diags);
  check_package_declarations(package, symbols, diags);
  for (ast::PortTypeDecl& type : package.port_types) {
    check_port_type(type, package, symbols, diags);
  }
  for (ast::AtomTypeDecl& type : package.atom_types) {
    check_atom_type(type, package, symbols, diags);
  }
  for (ast::ConnectorTypeDecl& type : package.connector_types) {
    check_connector_type(type, package, symbols, diags);
  }
  for (ast::CompoundTypeDecl& type : package.compound_types) {
    check_compound_type(type, package, symbols, diags);
  }
}

}  // namespace

void check_port_type(ast::PortTypeDecl& type, const ast::Package& package, const Symbols& symbols,
                     Diagnostics& diags) {
  NameScope names(diags);
  for (ast::ParamDecl& param : type.params) {
    names.declare(param.name);
    resolve_type(param.type, package, symbols, diags);
  }
}

}  // namespace detail

bool check(LoadedModel& model, Diagnostics& diags) {
  const detail::Symbols symbols(model);
  for (std::unique_ptr<ast::Package>& package : model.packages) {
    if (package) detail::check_package(*package, symbols, diags);
  }
  return !diags.has_errors();
}

}  // namespace smcbip::bipc
