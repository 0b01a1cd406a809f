// Package-level declarations: constants, extern data types (and their refinements), extern
// function and operator prototypes.
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Kind = ast::ValueType::Kind;

void check_constant(ast::ConstDataDecl& constant, ast::Package& package, const Symbols& symbols,
                    Diagnostics& diags) {
  resolve_type(constant.type, package, symbols, diags);
  if (!require_native_type(constant.type, "constant '" + constant.name.text + "'", diags)) {
    constant.type.resolved = {};
  }
  if (!constant.value) {
    diags.error(constant.name.loc, "constant '" + constant.name.text + "' must be initialised");
    return;
  }
  ExprContext ctx;
  ctx.where = ExprContext::Where::ConstInit;
  ctx.package = &package;
  ctx.constant = &constant;
  const ast::ValueType value = check_expression(*constant.value, ctx, symbols, diags);
  if (!assignable(value, constant.type.resolved)) {
    diags.error(start_of(*constant.value), "type mismatch: cannot assign " + type_name(value) +
                                               " to " + type_name(constant.type.resolved) +
                                               " constant '" + constant.name.text + "'");
  }
}

/// Refinement must not be cyclic: a type would be its own strict subtype. The refinements that
/// close a cycle are reported and cut, so that compatibility checks terminate.
void check_refinement_cycles(ast::Package& package, Diagnostics& diags) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
  const std::size_t n = package.extern_types.size();
  Graph graph(n);
  auto index = [&package](const ast::ExternTypeDecl* decl) -> int {
    for (std::size_t i = 0; i < package.extern_types.size(); ++i) {
      if (&package.extern_types[i] == decl) return static_cast<int>(i);
    }
    return -1;  // declared in another package: cannot be part of a cycle
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (const ast::TypeRef& parent : package.extern_types[i].refines) {
      const int j = index(parent.resolved.extern_type);
      if (parent.resolved.kind == Kind::Extern && j >= 0) boost::add_edge(i, j, graph);
    }
  }
  std::vector<int> component(n);
  if (n > 0) {
    boost::strong_components(graph, boost::make_iterator_property_map(
                                        component.begin(), boost::get(boost::vertex_index, graph)));
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (ast::TypeRef& parent : package.extern_types[i].refines) {
      const int j = index(parent.resolved.extern_type);
      if (parent.resolved.kind != Kind::Extern || j < 0 || component[i] != component[j]) continue;
      diags.error(parent.name.loc(), "extern type '" + package.extern_types[i].name.text +
                                         "' cannot refine '" + parent.name.text() +
                                         "': the refinements form a cycle");
      parent.resolved = {};
    }
  }
}

void check_extern_type(ast::ExternTypeDecl& type, const ast::Package& package,
                       const Symbols& symbols, Diagnostics& diags) {
  type.package = &package;
  for (ast::TypeRef& parent : type.refines) {
    const ast::ValueType resolved = resolve_type(parent, package, symbols, diags);
    if (resolved.kind != Kind::Error && resolved.kind != Kind::Extern) {
      diags.error(parent.name.loc(), "extern type '" + type.name.text +
                                         "' can only refine extern data types, not " +
                                         type_name(resolved));
      parent.resolved = {};
    }
  }
}

/// The operand counts an operator has for the native types.
bool arity_allowed(const std::string& op, std::size_t arity, std::string& expected) {
  static const std::vector<std::string> kBinary = {
      "||", "&&", "|", "^", "&", "==", "!=", "<", ">", "<=", ">=", "*", "/", "%"};
  if (op == "!" || op == "~") {
    expected = "1 operand";
    return arity == 1;
  }
  if (op == "+" || op == "-") {
    expected = "1 or 2 operands";
    return arity == 1 || arity == 2;
  }
  for (const std::string& binary : kBinary) {
    if (op == binary) {
      expected = "2 operands";
      return arity == 2;
    }
  }
  expected.clear();
  return false;
}

void check_function(ast::ExternFunctionDecl& f, const ast::Package& package, const Symbols& symbols,
                    Diagnostics& diags) {
  for (ast::ParamDecl& param : f.params) resolve_type(param.type, package, symbols, diags);
  if (f.result) resolve_type(*f.result, package, symbols, diags);
  if (!f.is_operator) return;
  std::string expected;
  if (!arity_allowed(f.name.text, f.params.size(), expected)) {
    if (expected.empty()) {
      diags.error(f.name.loc,
                  "'" + f.name.text +
                      "' is not an operator that can be declared "
                      "extern: expected one of || && | ^ & == != < > <= >= + - * / % ! ~");
    } else {
      diags.error(f.name.loc, "extern operator '" + f.name.text + "' takes " + expected + ", got " +
                                  std::to_string(f.params.size()));
    }
  }
  if (!f.result) {
    diags.error(f.name.loc, "extern operator '" + f.name.text + "' needs a return type");
  }
}

}  // namespace

void check_package_declarations(ast::Package& package, const Symbols& symbols, Diagnostics& diags) {
  for (ast::ExternTypeDecl& type : package.extern_types) {
    check_extern_type(type, package, symbols, diags);
  }
  check_refinement_cycles(package, diags);
  for (ast::ExternFunctionDecl& f : package.extern_functions) {
    check_function(f, package, symbols, diags);
  }
  for (ast::ConstDataDecl& constant : package.consts) {
    check_constant(constant, package, symbols, diags);
  }
}

}  // namespace smcbip::bipc::detail
