// Helpers shared by the checker's own files (expressions, atoms, connectors): name scopes,
// overload resolution, clock forms and the pieces of the atom and connector checks.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "bipc/ast/ast.h"
#include "bipc/check/detail/check_context.h"
#include "bipc/diagnostics.h"

namespace smcbip::bipc::detail {

/// One namespace of declarations: reports a second declaration of a name with a note at the first.
class NameScope {
 public:
  explicit NameScope(Diagnostics& diags) : diags_(diags) {}
  /// Records `name`; returns false (after reporting) when it was already declared. Empty names
  /// (left by a syntax error) are ignored.
  bool declare(const ast::Ident& name);

 private:
  Diagnostics& diags_;
  std::unordered_map<std::string, Location> first_;
};

/// Declares names in one scope in source order, so that notes point at the one written first.
void declare_in_source_order(std::vector<const ast::Ident*> names, Diagnostics& diags);

/// How a name is used: read in an expression or written by an assignment.
enum class NameUse { Read, Write };

/// Resolves a Name expression in its context, fills `expr.ref` and returns its type (clocks read
/// as float); reports undeclared names and names the context may not read.
ast::ValueType resolve_name(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                            Diagnostics& diags, NameUse use);

/// check_expression, except that a call of a function without result is accepted (as a
/// statement) when `allow_void` is set.
ast::ValueType check_value(ast::Expr& expr, const ExprContext& ctx, const Symbols& symbols,
                           Diagnostics& diags, bool allow_void);

/// Types a call of an extern function (arguments already checked by this function).
ast::ValueType check_call(ast::Expr& call, const ExprContext& ctx, const Symbols& symbols,
                          Diagnostics& diags, bool allow_void);

/// The extern operator prototypes named `symbol` with `operands.size()` parameters that accept
/// the operands, reduced to the strictly most precise one; nullptr when none applies. Sets
/// `ambiguous` when several apply and none is more precise than the others; `exists` when any
/// operator of that symbol and arity is visible.
struct OperatorMatch {
  const ast::ExternFunctionDecl* decl = nullptr;
  bool ambiguous = false;
  bool exists = false;
};
OperatorMatch match_operator(const std::string& symbol, const std::vector<ast::ValueType>& operands,
                             const ExprContext& ctx, const Symbols& symbols);

/// The first clock the expression reads (a resolved Name), or nullptr.
const ast::Expr* first_clock(const ast::Expr& expr);
/// Whether the expression reads a clock anywhere.
bool mentions_clock(const ast::Expr& expr);

/// Where an expression's text starts (a binary expression's location is its operator).
Location start_of(const ast::Expr& expr);

/// Requires the timed-automata forms of a (well-typed, bool) guard that reads clocks.
void check_clock_constraints(const ast::Expr& expr, Diagnostics& diags);

/// Whether a resolved name denotes a declaration written `const` (package constants included).
bool names_constant(const ast::Expr& expr, const ExprContext& ctx);

/// The written text of a name expression (`x`, `p.x`, `pkg.K`).
std::string name_text(const ast::Expr& expr);

/// `(int, bool)`: a list of types for messages.
std::string type_list(const std::vector<ast::ValueType>& types);

/// Index of the declaration named `name` in a vector of declarations with an `Ident name`, or -1.
template <typename Decl>
int index_of(const std::vector<Decl>& decls, const std::string& name) {
  for (std::size_t i = 0; i < decls.size(); ++i) {
    if (decls[i].name.text == name) return static_cast<int>(i);
  }
  return -1;
}

/// Index of `name` in a list of identifiers (places), or -1.
int index_of_ident(const std::vector<ast::Ident>& idents, const std::string& name);

/// The expression contexts whose guards may compare clocks.
bool clocks_comparable(ExprContext::Where where);

/// Whether a type is native: bool, int, float or string.
bool is_native(const ast::ValueType& type);
/// Whether a type is int or float.
bool is_numeric(const ast::ValueType& type);

// Declarations checked alike in several kinds of types (declarations.cpp).

/// Requires a native type for a parameter or constant (`what`: "parameter 'n'", "constant 'K'"),
/// whose type has been resolved; false, after reporting, when it is another (valid) type.
bool require_native_type(const ast::TypeRef& type, const std::string& what, Diagnostics& diags);

/// Resolves the types of the data of an atom or connector type and checks their initial values
/// (in `ctx`); constant data must have one.
void check_data_declarations(std::vector<ast::DataDecl>& data, const ExprContext& ctx,
                             const Symbols& symbols, Diagnostics& diags);

/// The port type named `type`; nullptr when there is none (reported unless nothing was written).
const ast::PortTypeDecl* resolve_port_type(const ast::QualifiedName& type,
                                           const ast::Package& package, const Symbols& symbols,
                                           Diagnostics& diags);

/// A port that binds data (an atom's port, a connector's exported port: `what` names its kind in
/// messages) binds one data per parameter of its port type (nullptr: unknown, not checked).
void check_bound_count(const std::string& what, const ast::Ident& port,
                       const ast::QualifiedName& type, const ast::PortTypeDecl* port_type,
                       std::size_t bound_count, Diagnostics& diags);

/// Reports a constant (`kind`: "data" or "parameter") bound by `binder` ("a port", "an exported
/// port"), which binds variables only since connectors write the data they are given.
void report_bound_constant(const ast::Ident& bound, const std::string& kind,
                           const std::string& binder, Diagnostics& diags);

/// The `k`-th data bound by such a port, `bound` of type `actual`, must have exactly the type of
/// the port type's `k`-th parameter (not checked when either is unknown).
void check_bound_type(const std::string& what, const ast::Ident& port,
                      const ast::PortTypeDecl* port_type, std::size_t k, const ast::Ident& bound,
                      const ast::ValueType& actual, Diagnostics& diags);

// Pieces of the atom check, each in its own file.

/// Checks the `@stochastic` annotations of one port of `atom`.
void check_stochastic(const ast::PortDecl& port, const ast::AtomTypeDecl& atom, Diagnostics& diags);

/// Checks the atom priorities: ports exist, wildcards, guards, and no cycle among the unguarded
/// ones.
void check_atom_priorities(ast::AtomTypeDecl& atom, const ExprContext& ctx, const Symbols& symbols,
                           Diagnostics& diags);

/// Whether `@SuppressWarning(...)` among `annotations` names `warning` (the Verimag front end's
/// names: "nondeterminism", "unboundcomponentport", "unboundconnectorport", "missingup"); it
/// silences that warning on the annotated element and everything inside it.
bool suppresses(const ast::Annotations& annotations, const std::string& warning);

/// Reports an annotation given twice on one declaration of the package, at the second one.
void check_annotation_redefinitions(const ast::Package& package, Diagnostics& diags);

/// Whether two (checked) guards can never hold together, as far as their text shows: a conjunct
/// of one is `!(g)` or `!(... || g || ...)` with every conjunct of `g` among the other's, or two
/// conjuncts compare the same native operands with no common order (`n < max`, `n == max`), or
/// equate one expression with two different literals.
bool guards_exclusive(const ast::Expr& a, const ast::Expr& b);

/// Reports transitions on one port (or internal ones) from nested sets of places: an error when
/// neither has a guard, a warning otherwise unless the guards are written as each other's
/// negation or `@SuppressWarning(nondeterminism)` is on the transition, its atom type or package.
void check_atom_determinism(const ast::AtomTypeDecl& atom, const ast::Package& package,
                            Diagnostics& diags);

/// Checks a connector's define expression: leaves are port parameters, each once, all present.
void check_define(ast::ConnectorTypeDecl& connector, Diagnostics& diags);

}  // namespace smcbip::bipc::detail
