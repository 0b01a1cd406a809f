// The syntax tree of SDL-PR text (OpenGEODE's textual SDL): systems, blocks, processes,
// procedures, states and transitions with their expressions, each node at its source location.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::sdl {

using bipc::Location;

/// Operators of expressions, after OpenGEODE's grammar (sdl92.g).
enum class Operator : std::uint8_t {
  None,
  Negate,  // unary -
  Not,
  Plus,
  Minus,
  Times,
  Divide,
  Mod,
  Rem,
  Concat,  // //
  Equal,
  NotEqual,
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  In,
  And,
  Or,
  Xor,
  Implies,
  AndThen,
  OrElse,
};

/// The spelling of an operator in SDL ("/=", "and then"); empty for None.
const char* spelling(Operator op);

/// An expression. Which fields are used depends on `kind`. A binary expression is located at its
/// operator, a call or field access where its callee or record starts, others at their first
/// token. A negative literal is the negation of a positive one.
struct Expr {
  enum class Kind : std::uint8_t {
    Integer,        // text: the digits as written
    Real,           // text: as written (`10.0`, `1e3`), or plus-infinity / minus-infinity
    String,         // text: contents, a doubled quote read as one
    BitString,      // `'0101'B`: text the binary digits
    OctetString,    // `'0A'H`: text the hexadecimal digits
    Boolean,        // text: "true" or "false"
    Name,           // text: the name as spelt (variables, constants, enumerated values)
    Field,          // `a.b` or `a!b`: operands[0] the record, text the field name
    Call,           // operands[0] the callee, operands[1..] the arguments (also indexing `a(i)`)
    ProcedureCall,  // `call p(args)` inside an expression: operands as for Call
    Unary,          // op, operands[0]
    Binary,         // op, operands[0] and [1]
    Conditional,    // `if c then a else b fi`: operands c, a, b
    Sequence,       // ASN.1 `{...}`: operands, with field_names (empty names for SEQUENCE OF)
    Choice,         // ASN.1 `alt:value`: text the alternative, operands[0] the value
  };
  Kind kind = Kind::Name;
  Operator op = Operator::None;
  std::string text;
  std::vector<Expr> operands;
  std::vector<std::string> field_names;
  Location at;
};

struct Action;

/// A sequence of actions; a terminator (nextstate, join, stop, return) is its last action.
struct Transition {
  std::vector<Action> actions;
  Location at;
};

/// One condition of a decision answer.
struct RangeCondition {
  enum class Kind : std::uint8_t {
    Value,   // `(3)`
    Open,    // `(>= 3)`: op is one of = /= < <= > >=
    Closed,  // `(1:5)`: low and high. As in OpenGEODE's grammar, `(name:x)` is a CHOICE value
  };
  Kind kind = Kind::Value;
  Operator op = Operator::Equal;
  Expr low;   // Value, Open: the value
  Expr high;  // Closed only
  Location at;
};

/// An answer of a decision: `(conditions):` or `else:`, and its transition.
struct Answer {
  bool is_else = false;
  std::vector<RangeCondition> conditions;
  Transition transition;
  Location at;
};

/// `decision question; answers enddecision;`; an `else:` answer is the last one.
struct Decision {
  bool is_any = false;  // `decision any;` (question unset)
  Expr question;
  std::vector<Answer> answers;
};

/// `for x in range(...)` or `for x in seq: body endfor`.
struct ForLoop {
  std::string variable;
  Expr iterable;    // a Call of `range` or a variable
  Transition body;  // a bare assignment list in the body reads as a task
  Location at;
};

/// One element of a task: an assignment, informal text or a for loop.
struct TaskElement {
  enum class Kind : std::uint8_t { Assignment, Informal, ForLoop };
  Kind kind = Kind::Assignment;
  Expr target, value;         // Assignment
  std::string text;           // Informal
  std::vector<ForLoop> loop;  // ForLoop: exactly one
  Location at;
};

/// One signal of an output: `sig(args)`.
struct OutputSignal {
  std::string name;
  std::vector<Expr> arguments;
  Location at;
};

/// One action of a transition. Which fields are used depends on `kind`.
struct Action {
  enum class Kind : std::uint8_t {
    Task,       // task (also a bare assignment, informal text or for loop: OpenGEODE's task_body)
    Output,     // outputs, optional to, via
    Call,       // name, arguments (set_timer, reset_timer, writeln... are calls too)
    Decision,   // decision
    Label,      // `name:` (a connector the transition goes through)
    Join,       // name
    NextState,  // name ("-" for the same state), via (entry point) or empty
    Stop,
    Return,  // value if any
  };
  Kind kind = Kind::Task;
  std::string name;
  std::string via;
  std::vector<Expr> arguments;
  std::vector<TaskElement> task;
  std::vector<OutputSignal> outputs;
  std::optional<Expr> to;
  std::optional<Expr> value;
  Decision decision;
  std::string comment;  // `comment '...'` as written, without quotes
  Location at;
};

/// A signal an input consumes, with the variables its parameters are stored in.
struct InputSignal {
  std::string name;
  std::vector<std::string> parameters;
  Location at;
};

/// `input sig(p), other;` or `input *;`, and the transition it fires.
struct Input {
  bool is_any = false;
  std::vector<InputSignal> signals;  // `input none;` (a spontaneous transition) reads as `none`
  std::optional<Expr> enabling;      // `input sig; provided expr;`: the enabling condition
  Transition transition;
  Location at;
};

/// A continuous signal: `provided expr; [priority n;]` and its transition.
struct ContinuousSignal {
  Expr condition;
  std::optional<Expr> priority;
  Transition transition;
  Location at;
};

/// `connect [exits];` in a state with a substructure: the transition taken on leaving it.
struct ExitConnection {
  std::vector<std::string> exit_points;  // empty: the default exit (`connect ;`); `*`: any
  Transition transition;
  Location at;
};

/// `state S, T;` / `state *;` / `state *(A, B);` / `state S via E;` ... `endstate;`.
struct State {
  std::vector<std::string> names;  // empty for `*`
  bool is_any = false;
  std::vector<std::string> except;  // `*(A, B)`
  std::string via;
  std::vector<Input> inputs;
  std::vector<ContinuousSignal> continuous;
  std::vector<std::string> saves;  // `*` for `save *`
  std::vector<ExitConnection> connections;
  std::string comment;
  Location at;
};

struct Variable {
  std::string name;
  std::string type;
  std::optional<Expr> initial;
  Location at;
};

struct Timer {
  std::string name;
  Location at;
};

/// `start;` or `start entry_point;` (in a substructure) and its transition.
struct Start {
  std::string entry_point;
  Transition transition;
  Location at;
};

/// `connection name: transition endconnection;`: a labelled transition reached by join.
struct FloatingLabel {
  std::string name;
  Transition transition;
  Location at;
};

struct Procedure;
struct CompositeState;

/// What a process, procedure or state substructure declares and does.
struct Body {
  std::vector<Variable> variables;
  std::vector<Timer> timers;
  std::vector<Procedure> procedures;
  std::vector<Start> starts;
  std::vector<State> states;
  std::vector<CompositeState> composite_states;
  std::vector<FloatingLabel> labels;
};

struct FormalParameter {
  enum class Direction : std::uint8_t { In, Out, InOut };
  Direction direction = Direction::In;
  std::string name;
  std::string type;
  Location at;
};

/// `procedure p; fpar ...; returns T; body endprocedure;` or an `external`/`referenced` one.
struct Procedure {
  std::string name;
  std::vector<FormalParameter> parameters;
  std::string return_type;  // empty: none
  std::string return_name;  // `returns res T;`
  bool is_external = false;
  bool is_referenced = false;
  std::string comment;
  Body body;
  Location at;
};

/// `state S; substructure [in (...);] [out (...);] body endsubstructure;`.
struct CompositeState {
  std::string name;
  bool is_aggregation = false;  // `state aggregation S;`: the substates run in parallel
  std::vector<std::string> entry_points, exit_points;
  Body body;
  Location at;
};

/// `process P; ... endprocess;`, `process type T; ...`, `process P : T;` or `process P
/// referenced;`.
struct Process {
  std::string name;
  bool is_type = false;
  std::string instance_of;                                   // `process P : T;`
  std::optional<Expr> initial_instances, maximum_instances;  // `process P(1, 1);`
  bool is_referenced = false;
  Body body;
  Location at;
};

struct SignalDeclaration {
  std::string name;
  std::vector<std::string> parameter_types;
  Location at;
};

/// One direction of a channel or signal route: `from A to B with s1, s2;`.
struct Path {
  std::string from, to;
  std::vector<std::string> signals;
  Location at;
};

/// A channel (between blocks and env) or a signal route (inside a block).
struct Channel {
  std::string name;
  bool no_delay = false;  // `channel c nodelay`
  std::vector<Path> paths;
  Location at;
};

/// `connect c and r;`: a channel joined to signal routes.
struct ChannelConnection {
  std::string channel;
  std::vector<std::string> routes;
  Location at;
};

struct UseClause {
  std::string package;
  std::vector<std::string> definitions;  // `use p/a, b;`
  std::string comment;
  Location at;
};

struct Block {
  std::string name;
  bool is_referenced = false;
  std::vector<SignalDeclaration> signals;
  std::vector<Channel> routes;
  std::vector<ChannelConnection> connections;
  std::vector<Block> blocks;
  std::vector<Process> processes;
  std::vector<Procedure> procedures;
  Location at;
};

struct System {
  std::string name;
  std::vector<UseClause> uses;
  std::vector<SignalDeclaration> signals;
  std::vector<Channel> channels;
  std::vector<Procedure> procedures;
  std::vector<Block> blocks;
  Location at;
};

/// The declarations of one `.pr` file, in order of kind.
struct SdlFile {
  std::vector<UseClause> uses;
  std::vector<System> systems;
  std::vector<Process> processes;
  std::vector<Procedure> procedures;
};

}  // namespace smcbip::taste2bip::sdl
