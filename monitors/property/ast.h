// The property language of PROPERTIES.md as parsed: declarations, queries, path formulas and
// the state expressions of their atomic predicates, with the positions they were read at.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::monitors {

using bipc::Location;

/// A time unit written after a number (`10ms`); None when the number has no suffix (the model's
/// clock unit, milliseconds by default).
enum class TimeUnit : std::uint8_t { None, Seconds, Milliseconds, Microseconds, Nanoseconds };

/// A number as written, or a name of a constant or parameter.
struct Value {
  Location at;
  std::string name;  // empty for a number
  std::string text;  // the number as written, without its unit
  double number = 0.0;
  bool integral = false;  // written without a fraction or exponent
  TimeUnit unit = TimeUnit::None;

  bool is_name() const { return !name.empty(); }
};

/// The bound of a temporal operator or of a run: none, a time interval [low, high] (`<=T` is
/// [0, T]), or a number of steps (`{k}`, `<=#k`).
struct Bound {
  enum class Kind : std::uint8_t { None, Time, Steps } kind = Kind::None;
  Value low, high;  // Time: both; Steps: high
};

/// What a name in a state expression refers to once resolved against a model
/// (resolve_names.h): indices into the IR, or into the file's declarations.
struct Reference {
  enum class Kind : std::uint8_t {
    Unresolved,
    Data,          // atom, data slot of its type
    Place,         // atom, place of its type
    Clock,         // atom, clock of its type
    Constant,      // index: PropertyFile::declarations
    Connector,     // index: System::connectors (fired)
    InternalPort,  // atom, port of its type (fired)
    Time,          // `time`: the global time, in the model's time unit
    Initial,       // `"init"`: the run's first state
    Deadlock,      // `deadlock`: nothing is enabled and nothing ever will be
    Timelock,      // `timelock`: time cannot progress
  } kind = Kind::Unresolved;
  std::uint32_t atom = 0;
  std::uint32_t index = 0;
};

/// Whether a reference is one of the language's own names (time, init, deadlock, timelock),
/// which the monitor answers itself rather than the model or the trace.
inline bool is_builtin(const Reference& r) {
  return r.kind == Reference::Kind::Time || r.kind == Reference::Kind::Initial ||
         r.kind == Reference::Kind::Deadlock || r.kind == Reference::Kind::Timelock;
}

/// A state expression (the inside of an atomic predicate): arithmetic, comparisons and the
/// functions PROPERTIES.md allows over data, places and clocks of the model.
struct Expr {
  enum class Kind : std::uint8_t {
    Number,  // value
    Bool,    // boolean
    Name,    // path, e.g. Channel.id_channel or Receiver.c2
    Negate,  // -a
    Add,
    Subtract,
    Multiply,
    Divide,
    Modulo,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    Equal,
    NotEqual,
    Call,  // function(args): abs, min, max
    Fired  // fired(connector): the step fired that interaction
  } kind = Kind::Number;
  Location at;
  Value value;
  bool boolean = false;
  std::string path;  // Name, Fired: the dotted path; Call: the function
  std::vector<std::unique_ptr<Expr>> operands;
  Reference reference;   // Name, Fired, once resolved
  bool is_bool = false;  // once resolved: a condition rather than a number
};

/// A path formula (BLTL with nesting, MTL with intervals). Atomic predicates hold an Expr.
struct Formula {
  enum class Kind : std::uint8_t {
    True,
    False,
    Atom,
    Not,
    And,
    Or,
    Implies,
    Iff,
    Next,
    Finally,
    Globally,
    Until,
    Release
  } kind = Kind::True;
  Location at;
  Bound bound;                 // Finally, Globally, Until, Release (and Next: none)
  std::unique_ptr<Expr> atom;  // Atom
  std::vector<std::unique_ptr<Formula>> operands;  // one (unary) or two (binary)
};

/// How a query compares the probability with its threshold (Hypothesis).
enum class Comparison : std::uint8_t { GreaterEqual, Greater, LessEqual, Less };

/// What an expectation query observes of each run: the maximum or minimum of its expression
/// over the run's states, its value at the run's bound, its time integral over the run, or how
/// many steps fired an interaction.
enum class Observation : std::uint8_t { Max, Min, Last, Integral, Count };

/// One query of a property file.
struct Query {
  enum class Kind : std::uint8_t {
    Estimate,     // P=? [ phi ], Pr[<=T](phi)
    Hypothesis,   // P>=theta [ phi ], Pr[<=T](phi) >= theta
    Expectation,  // E[<=T; N](max: expr), E=? [ max: expr ]
    Invariant,    // A[] phi: phi holds in every reachable state (exact, not statistical)
    Reachable,    // E<> phi: phi holds in some reachable state (exact, not statistical)
    Compare,      // Pr[<=T](phi) >= Pr[<=T2](psi): which of two probabilities is larger
    Simulate,     // simulate [<=T; N] { e1, e2 }: N trajectories of the expressions
  } kind = Kind::Estimate;
  Location at;
  Bound run;             // [<=T] or [#<=K]; Kind::None: the formula's horizon bounds the run
  bool pr_form = false;  // written Pr[...](...), E[...](...) (UPPAAL) rather than P/E...[ ]
  Comparison comparison = Comparison::GreaterEqual;
  Value threshold;                   // Hypothesis
  std::unique_ptr<Formula> formula;  // Estimate, Hypothesis, Invariant, Reachable (phi)
  // Expectation: the runs' number, what is observed of each run, and the expression.
  Value runs;  // also Simulate
  Observation observe = Observation::Max;
  std::unique_ptr<Expr> observed;
  // Compare: the second probability's run bound and formula (`comparison` relates the two).
  Bound other_run;
  std::unique_ptr<Formula> other;
  // Simulate: the expressions whose values along each run are written.
  std::vector<std::unique_ptr<Expr>> series;
};

/// `const NAME = value` or `param NAME = start:stop:step` / `{v1, v2, ...}`.
struct Declaration {
  enum class Kind : std::uint8_t { Constant, Parameter } kind = Kind::Constant;
  Location at;
  std::string name;
  Value value;                // Constant
  std::vector<Value> values;  // Parameter: a list, or start, stop, step of a range
  bool range = false;         // Parameter: values are start, stop, step
};

/// The declarations and queries of one property file, in file order.
struct PropertyFile {
  std::vector<Declaration> declarations;
  std::vector<Query> queries;
};

/// The normalised text of a formula or expression: one space around binary operators, bounds as
/// `[a,b]` / `{k}`. A formula is fully parenthesised: every operand that is not an atomic
/// predicate, and every compound predicate under a prefix operator, is in parentheses, so the
/// reader needs no precedence table; inside predicates, parentheses stand where precedence needs
/// them.
std::string to_string(const Expr& expr);
std::string to_string(const Formula& formula);
std::string to_string(const Bound& bound);
std::string to_string(const Value& value);
/// The normalised query, in the form it was written: `P=? [ phi ]`, `P>=0.9 [ phi ]`,
/// `Pr[<=100](phi)`, `Pr[<=100](phi) >= 0.9`, `E[<=100; 50](max: expr)`, `A[] phi`, `E<> phi`.
std::string to_string(const Query& query);
std::string to_string(const Declaration& declaration);
/// The names a query reads, where a constant or parameter may stand: its bounds, threshold,
/// run count, and the names of its predicates and expressions (dotted paths too).
std::set<std::string> names_read(const Query& query);

/// The keyword of an observation: `max`, `min`, `last`, `int`, `count`.
const char* observation_keyword(Observation observe);

}  // namespace smcbip::monitors
