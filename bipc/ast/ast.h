// The abstract syntax tree of a BIP2 package, as written by the user.
//
// The parser fills the syntactic fields; the checker fills the fields under "resolved by the
// checker" (never the parser), which the lowering to the IR then reads. Nodes are owned through
// std::unique_ptr or by value in vectors; a package is not modified after checking.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "bipc/timing.h"

namespace smcbip::bipc::ast {

/// A name as written, with where it was written.
struct Ident {
  std::string text;
  Location loc;
};

/// A dotted name `a.b.c` (package-qualified types, `comp.port`, `p.x` in connectors).
struct QualifiedName {
  std::vector<Ident> parts;
  Location loc() const { return parts.empty() ? Location{} : parts.front().loc; }
  std::string text() const;  // joined with '.'
};

/// `@name(key=value, key)`; unknown annotations are kept for later stages.
struct AnnotationParam {
  Ident key;
  std::optional<std::string>
      value;  // string literals unquoted and unescaped; ids/true/false as written
  Location value_loc;
};
struct Annotation {
  Ident name;
  std::vector<AnnotationParam> params;
  Location loc;  // the '@'
};
using Annotations = std::vector<Annotation>;

// ---------------------------------------------------------------------------------------------
// Types

struct ExternTypeDecl;
struct ExternFunctionDecl;
struct ConstDataDecl;
struct PortTypeDecl;
struct AtomTypeDecl;
struct ConnectorTypeDecl;
struct CompoundTypeDecl;
struct Package;

/// A value type as the checker sees it.
struct ValueType {
  enum class Kind : std::uint8_t { Error, Void, Bool, Int, Float, String, Extern };
  Kind kind = Kind::Error;
  const ExternTypeDecl* extern_type = nullptr;  // when kind == Extern
  bool operator==(const ValueType&) const = default;
};

/// A data type as written: `int`, `const float`, `pkg.ExtType`.
struct TypeRef {
  QualifiedName name;  // native names are single parts "int", "bool", "float", "string"
  bool is_const = false;
  Location loc;
  // Resolved by the checker.
  ValueType resolved;
};

// ---------------------------------------------------------------------------------------------
// Expressions and statements

enum class UnaryOp : std::uint8_t { Minus, Plus, Not, BitNot };
enum class BinaryOp : std::uint8_t {
  Or,
  And,
  BitOr,
  BitXor,
  BitAnd,
  Eq,
  Ne,
  Lt,
  Gt,
  Le,
  Ge,
  Add,
  Sub,
  Mul,
  Div,
  Mod
};

/// What a name in an expression denotes (resolved by the checker).
enum class RefKind : std::uint8_t {
  Unresolved,
  AtomData,       // index: data declaration index in the atom type
  AtomParam,      // index: parameter index of the atom type
  AtomClock,      // index: clock index in the atom type
  ConstData,      // const_data points at the package constant
  ConnectorData,  // index: data declaration index in the connector type
  PortParam,      // index: connector port parameter index; sub: port-type parameter index
  CompoundParam,  // index: parameter index of the compound type
  ComponentData,  // compound priority guard / export: index: component index; sub unused;
                  // member: the exported data name inside that component
};

struct Resolution {
  RefKind kind = RefKind::Unresolved;
  int index = -1;
  int sub = -1;
  const ConstDataDecl* const_data = nullptr;
  std::string member;
};

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  enum class Kind : std::uint8_t { Int, Float, String, Bool, Name, Call, Unary, Binary, Prime };
  Kind kind = Kind::Int;
  Location loc;

  std::int64_t int_value = 0;
  double float_value = 0.0;
  bool bool_value = false;
  std::string string_value;  // unescaped contents of a string literal
  QualifiedName name;        // Name; Call: the function name
  UnaryOp unary = UnaryOp::Minus;
  BinaryOp binary = BinaryOp::Add;
  std::vector<ExprPtr> operands;  // Unary: 1, Binary: 2, Call: arguments, Prime: 1 (`x'`)

  // Resolved by the checker.
  ValueType type;
  Resolution ref;                                // Name
  const ExternFunctionDecl* function = nullptr;  // Call, or a Unary/Binary on extern types
};

struct Statement;
using StatementPtr = std::unique_ptr<Statement>;

struct Statement {
  enum class Kind : std::uint8_t { Assign, Call, If };
  Kind kind = Kind::Assign;
  Location loc;
  ExprPtr target;  // Assign: a Name, or Prime(Name) for a clock rate `x' = 2.0`
  ExprPtr value;   // Assign: right-hand side; Call: the call expression; If: condition
  std::vector<StatementPtr> then_branch;
  std::vector<StatementPtr> else_branch;
};
using Block = std::vector<StatementPtr>;

// ---------------------------------------------------------------------------------------------
// Package-level declarations

struct ConstDataDecl {
  TypeRef type;
  Ident name;
  ExprPtr value;
  Annotations annotations;
  Location loc;
};

struct ExternTypeDecl {
  Ident name;
  std::vector<TypeRef> refines;
  std::optional<std::string> backend_name;  // `as "std::list<int>"`
  Annotations annotations;
  Location loc;
  // Resolved by the checker.
  const Package* package = nullptr;
};

struct ParamDecl {
  TypeRef type;
  Ident name;  // empty text for unnamed prototype parameters
  Location loc;
};

struct ExternFunctionDecl {
  bool is_operator = false;
  Ident name;  // function name, or the operator symbol ("+", "==", ...) for operators
  std::optional<TypeRef> result;
  std::vector<ParamDecl> params;
  Annotations annotations;
  Location loc;
};

struct PortTypeDecl {
  Ident name;
  std::vector<ParamDecl> params;
  Annotations annotations;
  Location loc;
};

// ---------------------------------------------------------------------------------------------
// Atom types

struct DataDecl {
  TypeRef type;
  Ident name;
  ExprPtr initial_value;  // `data int x = 3` (optional)
  bool exported = false;
  Annotations annotations;
  Location loc;
};

using bipc::ExternPolicy;
using bipc::TimeUnit;
using bipc::Urgency;

struct ClockDecl {
  Ident name;
  std::optional<TimeUnit> unit;  // unset: the model's default unit
  Annotations annotations;
  Location loc;
};

/// One port of a `port T p(x), q(y)` declaration; the modifiers are shared by the declaration.
struct PortDecl {
  QualifiedName type;
  Ident name;
  std::vector<Ident> bound_data;
  bool exported = false;
  std::optional<Ident> merged_as;  // `export port T p(), q() as e`
  bool is_extern = false;
  std::optional<std::string> backend_name;  // `extern port T p(x) as "Class"`
  std::optional<ExternPolicy> policy;
  Annotations annotations;
  Location loc;
  // Resolved by the checker.
  const PortTypeDecl* port_type = nullptr;
  std::vector<int> bound_data_index;  // atom data index per port-type parameter
};

struct ResumeClause {
  ExprPtr guard;  // optional
  Location loc;
};

struct InitialTransition {
  std::vector<Ident> to;
  Block action;
  std::optional<ResumeClause> resume;
  Location loc;
};

struct Transition {
  std::optional<Ident> port;  // empty: `internal`
  std::vector<Ident> from;
  std::vector<Ident> to;
  ExprPtr guard;  // optional
  std::optional<Urgency> urgency;
  Block action;
  bool has_action = false;
  std::optional<ResumeClause> resume;
  Annotations annotations;
  Location loc;
  // Resolved by the checker.
  int port_index = -1;
  std::vector<int> from_index, to_index;
};

struct AtomPriorityDecl {
  Ident name;
  std::optional<Ident> low, high;  // empty: the wildcard `*`
  Location low_loc, high_loc;
  ExprPtr guard;  // optional
  Location loc;
  // Resolved by the checker (-1 for `*`).
  int low_index = -1, high_index = -1;
};

struct InvariantDecl {
  Ident name;
  bool at = true;  // `at` or `from`
  std::vector<Ident> places;
  ExprPtr guard;
  Location loc;
  // Resolved by the checker.
  std::vector<int> place_index;
};

struct AtomTypeDecl {
  Ident name;
  std::vector<ParamDecl> params;
  std::vector<DataDecl> data;
  std::vector<PortDecl> ports;
  std::vector<ClockDecl> clocks;
  std::vector<Ident> places;
  InitialTransition initial;
  std::vector<Transition> transitions;
  std::vector<AtomPriorityDecl> priorities;
  std::vector<InvariantDecl> invariants;
  Annotations annotations;
  Location loc;
};

// ---------------------------------------------------------------------------------------------
// Connector types

/// A node of a `define` expression; `trigger` is the quote mark.
struct PortExpr {
  std::optional<Ident> port;       // a leaf names a port parameter
  std::vector<PortExpr> children;  // a nested `( ... )` group
  bool trigger = false;
  Location loc;
  // Resolved by the checker: the port parameter index of a leaf.
  int port_index = -1;
};

struct InteractionDecl {
  std::vector<Ident> ports;
  ExprPtr guard;  // optional
  bool has_up = false, has_down = false;
  Location up_loc, down_loc;  // the `up` and `down` keywords
  Block up, down;
  Annotations annotations;
  Location loc;
  // Resolved by the checker: port parameter indices.
  std::vector<int> port_index;
};

enum class ConnectorResume : std::uint8_t { None, Sync, Async };

struct ConnectorExportPort {
  QualifiedName type;
  Ident name;
  std::vector<Ident> bound_data;
  Annotations annotations;
  Location loc;
  // Resolved by the checker.
  const PortTypeDecl* port_type = nullptr;
  std::vector<int> bound_data_index;
};

struct ConnectorTypeDecl {
  Ident name;
  struct PortParam {
    QualifiedName type;
    Ident name;
    Location loc;
    const PortTypeDecl* port_type = nullptr;  // resolved by the checker
  };
  std::vector<PortParam> ports;
  std::vector<DataDecl> data;
  std::optional<ConnectorExportPort> export_port;
  std::vector<PortExpr> define;  // the top-level sequence `p' q r`
  Location define_loc;
  ConnectorResume resume = ConnectorResume::None;
  std::vector<InteractionDecl> interactions;
  Annotations annotations;
  Location loc;
};

// ---------------------------------------------------------------------------------------------
// Compound types

struct ComponentDecl {
  QualifiedName type;
  Ident name;
  std::vector<ExprPtr> args;
  Annotations annotations;
  Location loc;
  // Resolved by the checker: exactly one of them.
  const AtomTypeDecl* atom_type = nullptr;
  const CompoundTypeDecl* compound_type = nullptr;
};

struct ConnectorDecl {
  QualifiedName type;
  Ident name;
  std::vector<QualifiedName> ports;  // `comp.port` or `connector.port`
  Annotations annotations;
  Location loc;
  // Resolved by the checker.
  const ConnectorTypeDecl* connector_type = nullptr;
};

/// One side of a compound priority: `c:a.p,b.q`, `c:*` or `*:*`.
struct InteractionPattern {
  std::optional<Ident> connector;  // empty: `*:*`
  bool all_ports = false;          // `c:*`
  std::vector<QualifiedName> ports;
  Location loc;
  // Resolved by the checker: index into CompoundTypeDecl::connectors, or -1 for `*:*`.
  int connector_index = -1;
};

struct CompoundPriorityDecl {
  Ident name;
  InteractionPattern low, high;
  ExprPtr guard;  // optional
  Location loc;
};

struct PortExportDecl {
  std::vector<QualifiedName> ports;  // several: a merged export
  Ident name;
  Annotations annotations;
  Location loc;
};

struct DataExportDecl {
  QualifiedName data;
  Ident name;
  Annotations annotations;
  Location loc;
};

struct CompoundTypeDecl {
  Ident name;
  std::vector<ParamDecl> params;
  std::vector<ComponentDecl> components;
  std::vector<ConnectorDecl> connectors;
  std::vector<CompoundPriorityDecl> priorities;
  std::vector<PortExportDecl> port_exports;
  std::vector<DataExportDecl> data_exports;
  Annotations annotations;
  Location loc;
};

// ---------------------------------------------------------------------------------------------
// Packages

struct Package {
  QualifiedName name;
  std::vector<QualifiedName> uses;
  Annotations annotations;
  std::vector<ConstDataDecl> consts;
  std::vector<ExternTypeDecl> extern_types;
  std::vector<ExternFunctionDecl> extern_functions;  // functions and operators
  std::vector<PortTypeDecl> port_types;
  std::vector<AtomTypeDecl> atom_types;
  std::vector<ConnectorTypeDecl> connector_types;
  std::vector<CompoundTypeDecl> compound_types;
  Location loc;
  std::string path;  // the file it was read from
  // Resolved by the loader: the packages named by `uses`, in order.
  std::vector<const Package*> used_packages;
};

}  // namespace smcbip::bipc::ast
