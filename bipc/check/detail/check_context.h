// Internal interface shared by the parts of the checker: name lookup across packages and the
// typing of expressions and statements in each context where BIP2 allows them.
#pragma once

#include <string>
#include <vector>

#include "bipc/ast/ast.h"
#include "bipc/bipc.h"
#include "bipc/diagnostics.h"

namespace smcbip::bipc::detail {

/// The types and constants a package can name: its own and, qualified or not, those of the
/// packages it uses (transitively, as the Verimag compiler does).
class Symbols {
 public:
  explicit Symbols(const LoadedModel& model);

  const ast::PortTypeDecl* port_type(const ast::Package& from,
                                     const ast::QualifiedName& name) const;
  const ast::AtomTypeDecl* atom_type(const ast::Package& from,
                                     const ast::QualifiedName& name) const;
  const ast::CompoundTypeDecl* compound_type(const ast::Package& from,
                                             const ast::QualifiedName& name) const;
  const ast::ConnectorTypeDecl* connector_type(const ast::Package& from,
                                               const ast::QualifiedName& name) const;
  const ast::ExternTypeDecl* extern_type(const ast::Package& from,
                                         const ast::QualifiedName& name) const;
  const ast::ConstDataDecl* constant(const ast::Package& from,
                                     const ast::QualifiedName& name) const;
  /// Every extern function or operator prototype named `name` visible from `from`.
  std::vector<const ast::ExternFunctionDecl*> functions(const ast::Package& from,
                                                        const std::string& name) const;
  /// The package that declares a type (for qualified names in the IR).
  const ast::Package* package_of(const void* type_decl) const;

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

/// Where an expression or statement occurs; decides which names it may use and what it may do.
struct ExprContext {
  enum class Where {
    ConstInit,              // package constant initial value: constants only
    AtomInit,               // data initial values, initial transition action
    AtomGuard,              // transition guard: atom data, params, clocks (timed forms), constants
    AtomAction,             // transition action: may assign data, reset clocks, set rates
    AtomPriorityGuard,      // atom priority guard: data, params, constants; no clocks
    Invariant,              // invariant guard: clocks allowed (timed forms)
    Resume,                 // resume guard
    ConnectorGuard,         // `provided` of an interaction: port parameters of involved ports only
    ConnectorUp,            // `up`: read ports of the interaction, write connector data
    ConnectorDown,          // `down`: read connector data, write port parameters of involved ports
    CompoundPriorityGuard,  // exported data of components (`c.x`), compound parameters
    ComponentArgument,      // arguments of a component instance: compound params, constants
    StochasticParam,        // a `@stochastic` parameter: atom params and data
  };
  Where where = Where::AtomGuard;
  const ast::Package* package = nullptr;
  const ast::AtomTypeDecl* atom = nullptr;
  const ast::ConnectorTypeDecl* connector = nullptr;
  const ast::InteractionDecl* interaction = nullptr;  // its ports are the readable ones
  const ast::CompoundTypeDecl* compound = nullptr;
  const ast::ConstDataDecl* constant = nullptr;  // ConstInit: the constant being initialised
};

/// Types an expression, fills its resolved fields, reports errors; returns its type (Error kind
/// after an error, so that callers do not repeat it).
ast::ValueType check_expression(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                                Diagnostics& diags);

/// check_expression, then requires bool; also enforces the timed-automata forms for clocks.
void check_condition(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                     Diagnostics& diags, const char* what);

/// Checks a statement block (assignments, calls, if-then-else) in an action context.
void check_block(ast::Block& block, const ExprContext& ctx, const Symbols& symbols,
                 Diagnostics& diags);

/// Whether a value of type `from` may be used where `to` is expected (int -> float, subtypes of
/// extern types by `refine`).
bool assignable(const ast::ValueType& from, const ast::ValueType& to);

/// Resolves a written data type; reports unknown names.
ast::ValueType resolve_type(ast::TypeRef& type, const ast::Package& package, const Symbols& symbols,
                            Diagnostics& diags);

std::string type_name(const ast::ValueType& type);

/// Per-kind checks, each reporting every error it finds.
void check_package_declarations(ast::Package& package, const Symbols& symbols, Diagnostics& diags);
void check_port_type(ast::PortTypeDecl& type, const ast::Package& package, const Symbols& symbols,
                     Diagnostics& diags);
void check_atom_type(ast::AtomTypeDecl& type, const ast::Package& package, const Symbols& symbols,
                     Diagnostics& diags);
void check_connector_type(ast::ConnectorTypeDecl& type, const ast::Package& package,
                          const Symbols& symbols, Diagnostics& diags);
void check_compound_type(ast::CompoundTypeDecl& type, const ast::Package& package,
                         const Symbols& symbols, Diagnostics& diags);

/// The interface of a component type as seen from a compound: exported ports (with their port
/// types) and exported data (with their value types), for atoms and compounds alike.
struct ComponentInterface {
  struct PortEntry {
    std::string name;
    const ast::PortTypeDecl* type = nullptr;
  };
  struct DataEntry {
    std::string name;
    ast::ValueType type;
  };
  std::vector<PortEntry> ports;
  std::vector<DataEntry> data;
};
/// The interface of a component; empty when its type's instantiation never ends.
ComponentInterface interface_of(const ast::ComponentDecl& component, const Symbols& symbols);
/// interface_of for a component whose type the caller already knows to end (check_compound.cpp
/// finds those of all components at once).
ComponentInterface interface_of_ending(const ast::ComponentDecl& component, const Symbols& symbols);

/// Whether instantiating a compound type never ends: it contains itself, directly or through
/// other compound types, or contains a type that does (reported by check_compound_type).
/// interface_of must not descend into such a type.
bool instantiation_never_ends(const ast::CompoundTypeDecl& type, const Symbols& symbols);

/// Whether `ports` (connector port parameter indices) is an interaction the define allows,
/// computed on the tree without enumerating all interactions.
bool define_allows(const std::vector<ast::PortExpr>& define, const std::vector<int>& ports);

}  // namespace smcbip::bipc::detail
