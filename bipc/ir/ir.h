// The model IR: a checked BIP system flattened from one root instantiation.
//
// Types (atom, connector, port types) are kept once and shared by their instances; instances
// form the tree of the root compound. Guards, actions and transfer functions are compiled to a
// compact stack code (Code) that an engine evaluates without looking at names. The System is
// immutable once built and may be shared read-only by any number of threads.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "bipc/timing.h"

namespace smcbip::bipc::ir {

using Index = std::uint32_t;
inline constexpr Index kNone = 0xFFFFFFFFu;

enum class ValueKind : std::uint8_t { Void, Bool, Int, Float, String, Extern };

struct DataType {
  ValueKind kind = ValueKind::Int;
  Index extern_type = kNone;  // into System::extern_types when kind == Extern
  bool operator==(const DataType&) const = default;
};

/// A constant value (parameters of instances, folded constants).
struct Value {
  ValueKind kind = ValueKind::Int;
  bool b = false;
  std::int64_t i = 0;
  double f = 0.0;
  std::string s;
};

// ---------------------------------------------------------------------------------------------
// Compiled code: a stack machine over the slots of the executing context.

/// Where a Load/Store finds its slot, relative to the atom or connector being executed.
enum class Scope : std::uint8_t {
  AtomData,       // index: data slot of the atom
  AtomParam,      // index: parameter of the atom instance (read-only)
  Clock,          // index: clock of the atom (read: value; Store: reset to the value)
  ConnectorData,  // index: data slot of the connector
  PortParam,      // index: connector port parameter; arg: parameter of its port type
  InstanceData,   // index: atom instance in System::atoms; arg: data slot (compound priorities)
};

enum class Op : std::uint8_t {
  PushBool,    // imm.b
  PushInt,     // imm.i
  PushFloat,   // imm.f
  PushString,  // index: System::strings
  Load,        // scope, index, arg
  Store,       // scope, index, arg: pops the value
  StoreRate,   // index: clock whose rate becomes the popped value
  Neg,
  Not,
  BitNot,
  Add,
  Sub,
  Mul,
  Div,
  Mod,  // `kind` says Int or Float arithmetic
  BitAnd,
  BitOr,
  BitXor,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,               // `kind` is the compared operand kind
  IntToFloat,       // converts the top of the stack
  Call,             // index: System::functions, arg: argument count; pushes the result
  Jump,             // index: target instruction
  JumpIfFalse,      // pops; index: target
  JumpIfFalseKeep,  // `&&` short circuit: keeps false on the stack when jumping
  JumpIfTrueKeep,   // `||` short circuit: keeps true on the stack when jumping
  Pop,              // discards a call result used as a statement
};

/// Whether the instruction moves the program counter (its `index` is the target).
inline bool is_jump(Op op) {
  return op == Op::Jump || op == Op::JumpIfFalse || op == Op::JumpIfFalseKeep ||
         op == Op::JumpIfTrueKeep;
}
/// Eq..Ge: pops two operands of the instruction's kind, pushes a bool.
inline bool is_comparison(Op op) { return op >= Op::Eq && op <= Op::Ge; }
/// Add..Ge: pops two operands, pushes one result.
inline bool is_binary(Op op) { return op >= Op::Add && op <= Op::Ge; }

struct Instr {
  Op op = Op::PushInt;
  ValueKind kind = ValueKind::Int;
  Scope scope = Scope::AtomData;
  std::uint16_t arg = 0;
  Index index = 0;
  /// Div, Mod and Call, which can fault at run time: where the operator or call was written
  /// (System::sites), so the fault names that place; kNone elsewhere.
  Index site = kNone;
  union {
    bool b;
    std::int64_t i;
    double f;
  } imm{.i = 0};
};

/// An expression leaves exactly one value on the stack; a statement block leaves none.
/// An empty expression Code means "true" (no guard).
struct Code {
  std::vector<Instr> instrs;
  /// Its place in the system's numbering of all its code (number_code): compiled models find
  /// their function for this code by it.
  std::uint32_t id = 0;
  bool empty() const { return instrs.empty(); }
};

// ---------------------------------------------------------------------------------------------
// Types

struct Annotation {
  std::string name;
  std::vector<std::pair<std::string, std::optional<std::string>>> params;
  Location loc;
};

struct ExternType {
  std::string name;          // qualified name
  std::string backend_name;  // C++ spelling (`as "..."`, else the name)
  std::vector<Index> refines;
};

struct ExternFunction {
  std::string name;  // function name or operator symbol
  bool is_operator = false;
  std::optional<DataType> result;
  std::vector<DataType> params;
  std::vector<bool> const_params;
};

struct PortType {
  std::string name;
  std::vector<std::pair<std::string, DataType>> params;
};

struct Data {
  std::string name;
  DataType type;
  bool exported = false;
  Code initial_value;  // empty: default value
};

using bipc::ExternPolicy;
using bipc::TimeUnit;
using bipc::Urgency;

struct Clock {
  std::string name;
  TimeUnit unit = TimeUnit::Millisecond;
};

enum class Distribution : std::uint8_t {
  Normal,
  Exponential,
  Gamma,
  Chi2,
  Uniform,
  Lognormal,
  Weibull,
  Custom
};

/// `@stochastic(dist=..., clk=..., param=...)` on a port.
struct Stochastic {
  Distribution distribution = Distribution::Normal;
  Index clock = kNone;
  std::vector<Code> params;  // each an expression over atom parameters and data
  std::string custom_file;   // Custom: the empirical CDF file, resolved against the model's folder
};

struct Port {
  std::string name;
  Index type = 0;           // System::port_types
  std::vector<Index> data;  // atom data slot per port-type parameter
  bool exported = false;
  bool is_extern = false;
  ExternPolicy policy = ExternPolicy::Remember;
  std::string backend_name;
  std::optional<Stochastic> stochastic;
  std::vector<Annotation> annotations;
};

struct Resume {
  Code guard;  // empty: unconditional
};

struct Transition {
  Index port = kNone;  // kNone: internal transition
  std::vector<Index> from, to;
  Code guard;
  Code action;
  Urgency urgency = Urgency::Lazy;
  std::optional<Resume> resume;
  std::vector<Annotation> annotations;
  Location loc;
};

struct AtomPriority {
  std::string name;
  Index low = kNone, high = kNone;  // port indices; kNone is the wildcard
  Code guard;
};

struct Invariant {
  std::string name;
  bool at = true;
  std::vector<Index> places;
  Code guard;
};

/// A port of an atom's or compound's interface; several internal ports when merged (`as`).
struct InterfacePort {
  std::string name;
  Index type = 0;
  std::vector<Index> ports;  // internal port indices of the atom
};

struct AtomType {
  std::string name;  // qualified: package.Type
  std::vector<std::pair<std::string, DataType>> params;
  std::vector<Data> data;
  std::vector<Clock> clocks;
  std::vector<std::string> places;
  std::vector<Port> ports;
  std::vector<InterfacePort> interface;
  std::vector<Index> initial_places;
  Code initial_action;
  std::optional<Resume> initial_resume;
  std::vector<Transition> transitions;
  std::vector<AtomPriority> priorities;
  std::vector<Invariant> invariants;
  std::vector<Annotation> annotations;
};

/// A define expression node, kept as a tree: a broadcast over n ports has 2^(n-1) interactions,
/// too many to list, so engines enumerate what they need from the tree.
struct DefineNode {
  Index port = kNone;  // leaf: port parameter index
  std::vector<DefineNode> children;
  bool trigger = false;
};

struct InteractionCode {
  std::vector<Index> ports;  // sorted port parameter indices
  Code guard, up, down;
  std::vector<Annotation> annotations;
};

struct ConnectorType {
  std::string name;
  std::vector<std::pair<std::string, Index>> ports;  // name, port type
  std::vector<Data> data;
  std::optional<std::string> export_name;
  Index export_type = kNone;
  std::vector<Index> export_data;             // connector data slot per export port-type parameter
  std::vector<DefineNode> define;             // top-level sequence
  std::vector<InteractionCode> interactions;  // the `on` clauses; other defined ones: no code
  enum class Resume : std::uint8_t { None, Sync, Async } resume = Resume::None;
  std::vector<Annotation> annotations;
};

// ---------------------------------------------------------------------------------------------
// Instances

/// A port a connector can synchronise on: an atom's internal port, or a connector's export.
struct PortRef {
  enum class Kind : std::uint8_t { Atom, Connector } kind = Kind::Atom;
  Index instance = 0;  // System::atoms or System::connectors
  Index port = 0;      // atom: internal port index; connector: unused
  bool operator==(const PortRef&) const = default;
};

struct AtomInstance {
  std::string path;  // dotted path below the root instance, e.g. "ctrl.wdog"
  Index type = 0;
  Index parent = 0;  // System::compounds
  std::vector<Value> params;
  std::vector<Annotation> annotations;
};

struct ConnectorInstance {
  std::string path;
  Index type = 0;
  Index parent = 0;
  /// Per port parameter, the ports it may bind (more than one through merged exports).
  std::vector<std::vector<PortRef>> bound;
  /// Per port parameter, the binding as written (`holder.port`), which traces print.
  std::vector<std::string> bound_names;
  /// Per port parameter, whether the binding reaches a connector's export through a compound's
  /// exported port: engines then see only the sub-connector's maximal interactions, as the
  /// Verimag engine's compound export ports offer them.
  std::vector<bool> bound_through_compound;
  Index bound_by = kNone;  // the connector whose port binds this one's export, if any
  /// Every connector binding this one's export, in instance order (bound_by is the first). An
  /// export may feed several connectors, as an atom port may (BIP2 language reference).
  std::vector<Index> bound_by_all;
  std::vector<Annotation> annotations;
};

struct PatternSide {
  Index connector = kNone;  // System::connectors; kNone: `*:*`
  bool all_ports = false;   // `c:*`
  std::vector<PortRef> ports;
};

struct Priority {
  std::string name;
  PatternSide low, high;
  Code guard;  // loads use Scope::InstanceData
};

struct CompoundInstance {
  std::string path;  // "" for the root
  std::string type;  // qualified type name
  Index parent = kNone;
  std::vector<Index> atoms, compounds, connectors;  // direct children
  std::vector<Priority> priorities;
  /// Exported ports: name -> the ports it stands for.
  std::map<std::string, std::vector<PortRef>> exported_ports;
  /// Exported data: name -> (atom instance, data slot).
  std::map<std::string, std::pair<Index, Index>> exported_data;
  std::vector<Annotation> annotations;
};

struct System {
  std::string root_name = "ROOT";
  std::string root_type;
  std::vector<std::string> strings;  // string literal pool
  std::vector<ExternType> extern_types;
  std::vector<ExternFunction> functions;
  std::vector<PortType> port_types;
  std::vector<AtomType> atom_types;
  std::vector<ConnectorType> connector_types;
  std::vector<AtomInstance> atoms;
  std::vector<ConnectorInstance> connectors;
  std::vector<CompoundInstance> compounds;  // compounds[0] is the root
  // From `@cpp(include=..., src=...)`: sources resolved against the folder of the package that
  // names them, headers as written, and those folders as include directories.
  std::vector<std::string> cpp_includes, cpp_sources, cpp_include_dirs;
  std::uint32_t code_count = 0;  // Code::id runs from 0 to code_count - 1
  /// The source locations Instr::site names, and the files a Location's `file` indexes (the
  /// front end's SourceFiles): what run-time faults are reported at.
  std::vector<Location> sites;
  std::vector<std::string> source_files;
};

/// What a Code is for, as the engines run it.
enum class CodeUse : std::uint8_t {
  Value,      // an expression evaluated to a value (initial values, stochastic parameters)
  Statement,  // a statement block executed for its effects (actions, up, down)
  Guard,      // a condition, possibly over clocks (transition guards, resumes, invariants,
              // priorities, connector guards)
};

/// Calls `visit(code, use)` on every Code of the system (const or not) in this order: atom
/// types (data initial values, initial action and resume, ports' stochastic parameters,
/// transitions' guard, action and resume, priorities, invariants), connector types (data initial
/// values, interactions' guard, up and down), then compounds' priority guards.
template <class SystemT, class Visit>
void for_each_code(SystemT& system, Visit&& visit) {
  for (auto& type : system.atom_types) {
    for (auto& d : type.data) visit(d.initial_value, CodeUse::Value);
    visit(type.initial_action, CodeUse::Statement);
    if (type.initial_resume) visit(type.initial_resume->guard, CodeUse::Guard);
    for (auto& port : type.ports) {
      if (!port.stochastic) continue;
      for (auto& param : port.stochastic->params) visit(param, CodeUse::Value);
    }
    for (auto& t : type.transitions) {
      visit(t.guard, CodeUse::Guard);
      visit(t.action, CodeUse::Statement);
      if (t.resume) visit(t.resume->guard, CodeUse::Guard);
    }
    for (auto& p : type.priorities) visit(p.guard, CodeUse::Guard);
    for (auto& inv : type.invariants) visit(inv.guard, CodeUse::Guard);
  }
  for (auto& type : system.connector_types) {
    for (auto& d : type.data) visit(d.initial_value, CodeUse::Value);
    for (auto& code : type.interactions) {
      visit(code.guard, CodeUse::Guard);
      visit(code.up, CodeUse::Statement);
      visit(code.down, CodeUse::Statement);
    }
  }
  for (auto& compound : system.compounds) {
    for (auto& p : compound.priorities) visit(p.guard, CodeUse::Guard);
  }
}

/// Numbers every Code of the system (Code::id, System::code_count) in for_each_code's order.
void number_code(System& system);

/// The last component of a dotted path or qualified name: "a.b.c" -> "c".
std::string last_component(const std::string& path);

/// Whether the atom type's net is a state machine: one initial place and every transition from
/// one place to one place, so that exactly one place is marked at any time.
bool is_state_machine(const AtomType& type);

/// The BIP name of a value kind: "void", "bool", "int", "float", "string", "extern".
const char* value_kind_name(ValueKind kind);

}  // namespace smcbip::bipc::ir
