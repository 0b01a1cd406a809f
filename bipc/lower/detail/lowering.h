// Internal interface of the lowering to the IR: the type tables of one run, code compilation
// and the constant evaluator shared by constants, component arguments and code folding.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "bipc/ast/ast.h"
#include "bipc/bipc.h"
#include "bipc/diagnostics.h"
#include "bipc/ir/ir.h"

namespace smcbip::bipc::lower {

/// The meaning of names that only an instance can give: compound parameters and the exported
/// data of sibling components (compound priority guards, component arguments).
class InstanceBindings {
 public:
  virtual ~InstanceBindings() = default;
  /// The value of parameter `index` of the compound instance, or null when unknown.
  virtual const ir::Value* compound_param(int index) const = 0;
  /// The (atom instance, data slot) that `component.member` denotes, if it resolves.
  virtual std::optional<std::pair<ir::Index, ir::Index>> component_data(
      int component, const std::string& member) const = 0;
};

/// Runs instructions [begin, end) of `code`, which must leave one value; nullopt when the
/// segment reads state, calls a function, divides by zero or is malformed. Jump targets are
/// absolute indices into `code`.
std::optional<ir::Value> evaluate_constant(const std::vector<ir::Instr>& code, std::size_t begin,
                                           std::size_t end,
                                           const std::vector<std::string>& strings);

/// Converts a constant to `to` where BIP allows it implicitly (int to float); others unchanged.
ir::Value convert_value(ir::Value value, ir::ValueKind to);

/// Maps a checker type to an IR value kind (Error and Void map to Void).
ir::ValueKind value_kind(const ast::ValueType& type);

/// The System under construction and the type tables that keep each type lowered once.
class Lowering {
 public:
  Lowering(const LoadedModel& model, ir::System& system, Diagnostics& diags);

  ir::System& system() { return system_; }
  Diagnostics& diags() { return diags_; }

  /// Index of a type in the System, lowering it (and what it refers to) on first use.
  ir::Index extern_type(const ast::ExternTypeDecl& decl);
  ir::Index function(const ast::ExternFunctionDecl& decl);
  ir::Index port_type(const ast::PortTypeDecl& decl);
  ir::Index atom_type(const ast::AtomTypeDecl& decl);
  ir::Index connector_type(const ast::ConnectorTypeDecl& decl);
  ir::DataType data_type(const ast::ValueType& type);

  /// Index of a string literal in System::strings (each distinct string once).
  ir::Index string(const std::string& text);
  /// Index in System::sites of an instruction written at `at` that can fault at run time.
  ir::Index site(Location at);
  /// The value of a package constant, evaluated once; nullopt (reported) when not constant.
  std::optional<ir::Value> constant(const ast::ConstDataDecl& decl);

  /// `package.Name` for a declaration of a loaded package.
  std::string qualified_name(const void* decl, const std::string& name) const;
  const ast::Package* package_of(const void* decl) const;

  /// Interface port of an atom type by name (index into AtomType::interface).
  std::optional<ir::Index> atom_interface_port(ir::Index atom_type, const std::string& name) const;
  /// Data slot of an atom type by name.
  std::optional<ir::Index> atom_data(ir::Index atom_type, const std::string& name) const;

  /// Reports a resolution the checker should have filled; lowering goes on without it.
  void internal_error(Location at, const std::string& what);

 private:
  using NameIndex = std::unordered_map<std::string, ir::Index>;
  void lower_atom_type(const ast::AtomTypeDecl& decl, ir::Index index);
  void lower_connector_type(const ast::ConnectorTypeDecl& decl, ir::Index index);
  void index_packages(const LoadedModel& model);

  ir::System& system_;
  Diagnostics& diags_;
  std::unordered_map<const void*, const ast::Package*> package_of_;
  std::unordered_map<const void*, ir::Index> types_;  // every lowered declaration
  NameIndex strings_;
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, ir::Index> sites_;
  std::unordered_map<const ast::ConstDataDecl*, std::optional<ir::Value>> constants_;
  std::unordered_set<const ast::ConstDataDecl*> evaluating_;  // guards against cycles
  std::vector<NameIndex> atom_interface_, atom_data_;         // per atom type
};

/// Compiles expressions and statement blocks to stack code (see ir.h), folding constants.
class CodeCompiler {
 public:
  /// `bindings` is null outside instances (types, package constants).
  explicit CodeCompiler(Lowering& lowering, const InstanceBindings* bindings = nullptr)
      : lowering_(lowering), bindings_(bindings) {}

  /// An expression leaving one value converted to `expected` (Void: unconverted); empty code
  /// for a null expression (a missing guard).
  ir::Code expression(const ast::Expr* expr, ir::ValueKind expected = ir::ValueKind::Void);
  /// A statement block leaving nothing on the stack.
  ir::Code block(const ast::Block& block);
  /// `@stochastic` parameter text: a number literal or an atom parameter or data name, as a
  /// float; nullopt when it is neither.
  std::optional<ir::Code> stochastic_param(const std::string& text, const ast::AtomTypeDecl& atom);

 private:
  /// The kind of value an expression leaves, and whether it reads no state.
  struct Shape {
    ir::ValueKind kind = ir::ValueKind::Void;
    bool constant = false;
  };
  using Instrs = std::vector<ir::Instr>;

  Shape expr(const ast::Expr& e, Instrs& out);
  Shape name(const ast::Expr& e, Instrs& out);
  Shape call(const ast::Expr& e, const ast::ExternFunctionDecl& f, Instrs& out);
  Shape unary(const ast::Expr& e, Instrs& out);
  Shape binary(const ast::Expr& e, Instrs& out);
  Shape logical(const ast::Expr& e, Instrs& out);
  Shape push_value(const ir::Value& value, Instrs& out);
  void fold(std::size_t begin, Shape shape, Instrs& out);
  /// `value` if it fits an instruction's 16-bit `arg`; reports it otherwise.
  ir::Index check_arg(std::size_t value, Location at);
  void statement(const ast::Statement& s, Instrs& out);
  void assignment(const ast::Statement& s, Instrs& out);
  void if_statement(const ast::Statement& s, Instrs& out);

  Lowering& lowering_;
  const InstanceBindings* bindings_;
};

/// Parses a `@stochastic(dist=..., clk=..., param=...)` annotation of a port of `atom`;
/// reports malformed ones.
std::optional<ir::Stochastic> lower_stochastic(const ast::Annotation& annotation,
                                               const ast::AtomTypeDecl& atom,
                                               const ast::Package* package, Lowering& lowering);

/// Checks that only the flattened system reveals: a connector reaching one atom through two
/// of its ports, two stochastic ports in one interaction, cycles of hierarchical connectors.
/// `connector_locs` gives the declaration of each connector instance.
void check_instances(const ir::System& system, const std::vector<Location>& connector_locs,
                     Diagnostics& diags);

/// Copies annotations as they are.
std::vector<ir::Annotation> lower_annotations(const ast::Annotations& annotations);

}  // namespace smcbip::bipc::lower
