// The state of one SDL process's translation to a BIP atom: the data in scope, the atom text as
// it grows (places, ports, transitions), and the open step that actions add statements to.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/sdl/sdl_ast.h"
#include "taste2bip/translate/bip_types.h"
#include "taste2bip/translate/sdl_atom.h"
#include "taste2bip/translate/signature.h"

namespace smcbip::taste2bip::detail {

/// A value in BIP data: the data `data` (a variable, a field of it, an interface parameter)
/// and its leaves relative to it; `type` is its ASN.1 type with references followed (null for
/// the SDL builtin scalars).
struct Ref {
  std::string data;
  std::vector<Leaf> leaves;
  const asn1::Type* type = nullptr;
};

/// A scalar BIP expression and its kind (`int`, `bool`, `float`, `string`, or empty when the
/// kind is not known).
struct Scalar {
  std::string text;
  std::string kind;
};

/// What an SDL name stands for in a scope: a value in data, or (a `for` variable) a number.
struct Binding {
  std::optional<Ref> ref;
  std::int64_t number = 0;
};

/// A transition being written: from a place (or the atom's initial transition) on a port,
/// with its guard and statements; closed by naming the place it goes to.
struct Step {
  bool initial = false;
  std::string port;
  std::string from;
  std::string guard;
  std::vector<std::string> statements;
};

/// Where the steps of a translated action sequence end when they do not reach a terminator:
/// falling off its end, or (inside an inlined procedure) at a `return`.
struct Outcome {
  std::vector<Step> falls, returns;
  void merge(Outcome other);
};

/// The transition a chain of steps belongs to: the state it started in (for `nextstate -`),
/// the provided interface whose `return` ends it, and the out parameters copied before.
struct Chain {
  std::string origin;  // the stable state's place; empty for the start transition
  std::string key;     // distinguishes the places of labels per chain context
  const SignalInterface* serving = nullptr;
  std::string busy;  // the aggregation's busy data, for a chain that starts in one of its regions
  std::vector<std::pair<Ref, Ref>> out_copies;  // interface data <- variable, at the return
};

/// A label's continuation: the actions after it in `actions`.
struct LabelSite {
  const std::vector<sdl::Action>* actions = nullptr;
  std::size_t index = 0;
  bool top_level = true;
};

/// A body whose states are flattened into places: the process's, or a composite state's
/// substructure (its places prefixed with `<Composite>_`).
struct Level {
  const sdl::Body* body = nullptr;
  std::string prefix;
  const Level* parent = nullptr;
  const sdl::CompositeState* composite = nullptr;  // null for the process
  std::map<std::string, std::string> states;       // folded name -> place
  std::map<std::string, const sdl::CompositeState*> composites;
  const sdl::Procedure* entry = nullptr;  // the substructure's `entry` and `exit` procedures
  const sdl::Procedure* exit = nullptr;
  /// A state aggregation's data that is true while one of its regions runs a transition.
  std::string busy;
};

/// A state the process rests in: a place and the level that declares it.
struct StableState {
  std::string place;
  std::string name;  // folded
  const Level* level = nullptr;
};

/// A transition of a state block, with the level whose names it sees.
struct Handler {
  const sdl::Input* input = nullptr;
  const sdl::InputSignal* signal = nullptr;
  const Level* level = nullptr;
};

/// The entry of a composite state through an entry point (empty: its default start).
struct PendingEntry {
  const sdl::CompositeState* composite = nullptr;
  std::string entry;
  std::string place;
  std::string origin;  // the SDL state whose transition enters it ("" for the start)
};

class Translator {
 public:
  Translator(const FunctionSignature& function, const sdl::Process& process,
             const std::vector<const sdl::Procedure*>& procedures, const asn1::DataView& data,
             bipc::Diagnostics& diags);
  std::optional<AtomType> run();

  // Names and errors (sdl_atom.cpp). While `quiet_`, errors only mark the attempt failed.
  void error(const bipc::Location& at, const std::string& message);
  std::string fresh(const std::string& base);
  void reserve(const std::string& name) { used_.insert(name); }

  // Declarations (sdl_atom.cpp).
  void declare_timers();
  void declare_variables();
  void declare_context();
  void declare_procedure(const sdl::Procedure& p, const std::string& level_prefix = {});
  std::string text() const;

  // Variables and values (sdl_atom_data.cpp).
  std::optional<std::vector<Leaf>> leaves_of_type(const std::string& type, const bipc::Location& at,
                                                  const asn1::Type** definition);
  void declare_variable(const std::string& data, const std::vector<Leaf>& leaves);
  std::optional<Ref> declare_sdl_variable(const sdl::Variable& v, const std::string& prefix);
  static std::string default_value(const Leaf& leaf);
  std::optional<Ref> field(const Ref& ref, const std::string& name, const bipc::Location& at);
  std::optional<Ref> element(const Ref& ref, std::int64_t index, const bipc::Location& at);
  Ref interface_ref(const SignalInterface& i, const SignalParameter& p) const;

  // Expressions (sdl_atom_expr.cpp, sdl_atom_builtins.cpp).
  std::optional<Ref> reference(const sdl::Expr& e);
  std::optional<Scalar> scalar(const sdl::Expr& e, const asn1::Type* hint = nullptr);
  std::optional<Scalar> name_value(const sdl::Expr& e, const asn1::Type* hint);
  std::optional<Scalar> binary(const sdl::Expr& e);
  /// The variable (or part of one) `e` names, as a scalar; an error for a structured value.
  std::optional<Scalar> scalar_reference(const sdl::Expr& e);
  /// `e` as a guard: a bool expression, else an error naming `what` it is the condition of.
  std::optional<Scalar> condition(const sdl::Expr& e, const char* what);
  std::optional<Scalar> call_value(const sdl::Expr& e, const asn1::Type* hint);
  std::optional<Scalar> bookkeeping_value(const std::string& f, const sdl::Expr& e);
  std::optional<std::int64_t> constant(const sdl::Expr& e);
  std::optional<Scalar> equality(const sdl::Expr& a, const sdl::Expr& b, bool equal,
                                 const bipc::Location& at);
  const asn1::Type* type_of(const sdl::Expr& e);

  // Assignments (sdl_atom_assign.cpp).
  bool assign(const Ref& target, const sdl::Expr& value, std::vector<std::string>& out);
  bool assign_ref(const Ref& target, const Ref& source, const bipc::Location& at,
                  std::vector<std::string>& out);
  bool assign_sequence(const Ref& target, const sdl::Expr& value, std::vector<std::string>& out);
  bool assign_conditional(const Ref& target, const sdl::Expr& value, std::vector<std::string>& out);
  bool assign_choice(const Ref& target, const sdl::Expr& value, std::vector<std::string>& out);
  std::optional<std::string> literal_equals(const Ref& r, const sdl::Expr& literal);
  bool assign_statement(const sdl::Expr& target, const sdl::Expr& value,
                        std::vector<std::string>& out);

  // Steps (sdl_atom_steps.cpp).
  void close(Step step, const std::string& to);
  Step open(const std::string& from, std::size_t branch = 0, std::string guard = {});
  std::string place(const Chain& chain);
  std::string branch_port(std::size_t k);

  // Actions (sdl_atom_actions.cpp, sdl_atom_decision.cpp, sdl_atom_calls.cpp).
  Outcome actions(const std::vector<sdl::Action>& list, std::size_t from, Step step, Chain& chain);
  bool action(const sdl::Action& a, Step& step, Chain& chain, Outcome& out, bool& ended);
  bool task(const sdl::TaskElement& t, Step& step, Chain& chain, Outcome& out, bool& ended);
  // Loops (sdl_atom_loops.cpp).
  bool for_loop(const sdl::ForLoop& loop, Step& step, Chain& chain, Outcome& out, bool& ended);
  bool unrolled(const sdl::ForLoop& loop, const std::vector<Binding>& values, Step& step,
                Chain& chain, Outcome& out, bool& ended);
  bool loop_in_net(const sdl::ForLoop& loop, Step& step, Chain& chain, Outcome& out);
  bool elements_in_net(const sdl::ForLoop& loop, const Ref& seq, const Leaf& length, Step& step,
                       Chain& chain, Outcome& out);
  bool net_loop(const sdl::ForLoop& loop, const std::string& var, const std::string& low,
                const std::string& high, std::int64_t by, std::vector<std::string> prelude,
                const Binding& binding, Step& step, Chain& chain, Outcome& out);
  bool element_values(const Ref& seq, const sdl::Expr& sequence, std::vector<Binding>& values);
  bool next_state(const sdl::Action& a, Step step, Chain& chain);
  bool return_action(const sdl::Action& a, Step& step, Chain& chain, Outcome& out);
  void terminate(Step step, const std::string& target, Chain& chain);
  /// The one step that continues after `falls` (a place joining them when there are several);
  /// nullopt when there is none.
  std::optional<Step> join_falls(std::vector<Step> falls, Chain& chain);
  Outcome decision(const sdl::Action& a, Step step, Chain& chain);
  std::optional<std::string> structured_answer(const sdl::Expr& question,
                                               const sdl::Answer& answer);
  std::optional<std::string> answer_guard(const sdl::Expr& question, const sdl::Answer& answer);
  Outcome label(const std::string& name, const bipc::Location& at, Step step, Chain& chain,
                bool sequential, const std::vector<sdl::Action>* list, std::size_t index);
  bool output(const sdl::OutputSignal& s, Step& step, Chain& chain);
  bool call(const sdl::Action& a, Step& step, Chain& chain, Outcome& out, bool& ended);
  bool timer_call(const sdl::Action& a, bool set, Step& step);
  bool sdl_timer_call(const sdl::Action& a, Step& step);
  bool write_call(const sdl::Action& a, bool newline, Step& step);
  bool interface_call(const SignalInterface& r, const std::vector<sdl::Expr>& args,
                      const bipc::Location& at, Step& step, Chain& chain);
  bool procedure_call(const sdl::Procedure& p, const sdl::Action& a, Step& step, Chain& chain,
                      Outcome& out, bool& ended);
  const sdl::Procedure* choose_procedure(const std::string& name, std::size_t arguments);
  bool call_for_value(const sdl::Expr& target, const sdl::Expr& call, Step& step, Chain& chain,
                      Outcome& out, bool& ended);
  std::optional<std::string> state_place(const std::string& name, const std::string& via,
                                         const std::string& origin, const bipc::Location& at);

  // States (sdl_atom_states.cpp).
  void collect_states();
  Level* build_level(const sdl::Body& body, const std::string& prefix, const Level* parent,
                     const sdl::CompositeState* composite);
  void declare_level(Level& level);
  std::string entry_place(const sdl::CompositeState& c, const std::string& entry,
                          const std::string& origin);
  void translate_entries();
  void enter_regions(const PendingEntry& e);
  const sdl::CompositeState* owner_region(const Level& aggregation, const std::string& key) const;
  bool has_input(const sdl::Body& body, const std::string& key) const;
  /// The region of a state aggregation that `state` lies in, with the aggregation's level.
  std::pair<const sdl::CompositeState*, const Level*> region_of(const StableState& state) const;
  /// `step` made the start of a chain of a region of `aggregation` (none: unchanged).
  void start_in_region(const Level* aggregation, Step& step, Chain& chain) const;
  void refuse_outer_transitions(
      const StableState& state, const Level& aggregation,
      const std::vector<std::pair<const sdl::State*, const Level*>>& blocks);
  bool exit_composite(const sdl::Action& a, Step& step, Chain& chain, Outcome& out);
  bool inline_hook(const sdl::Procedure* p, Step& step, Chain& chain, const bipc::Location& at);
  std::vector<std::pair<const sdl::State*, const Level*>> blocks_of(const StableState& s) const;
  void collect_body_labels(const sdl::Body& body, std::map<std::string, LabelSite>& into);
  void collect_labels(const std::vector<sdl::Action>& list, bool top_level,
                      std::map<std::string, LabelSite>& into);
  void translate_start();
  void translate_state(const StableState& state);
  void refuse_unknown_inputs(const std::map<std::string, Handler>& handled);
  bool state_applies(const sdl::State& s, const std::string& state) const;
  void input_transition(const std::string& state, const SignalInterface& p, const Handler& h);
  void fault_transition(const std::string& state, const SignalInterface& p, const Handler& h);
  void timer_transition(const std::string& state, const std::string& timer, const Handler& h);
  void continuous_transitions(
      const StableState& state,
      const std::vector<std::pair<const sdl::State*, const Level*>>& blocks);
  void chain_end(const Outcome& outcome, const bipc::Location& at);
  void add_state(Level& level, const std::string& name);
  void scan_nextstates(Level& level, const std::vector<sdl::Action>& list);

  // What the translation sees.
  const FunctionSignature& function_;
  const sdl::Process& process_;
  const asn1::DataView& data_;
  bipc::Diagnostics& diags_;
  /// By folded name; a process may declare a name twice (text and graphics), the call picks
  /// the one whose parameters it matches.
  std::map<std::string, std::vector<const sdl::Procedure*>> procedures_;
  std::map<const sdl::Procedure*, std::map<std::string, Binding>> procedure_scopes_;
  std::map<const sdl::Procedure*, std::vector<Ref>> procedure_parameters_;
  std::vector<std::string> initial_statements_;
  std::vector<std::map<std::string, Binding>> scopes_;  // innermost last
  std::vector<std::map<std::string, LabelSite>> label_tables_;
  std::vector<const sdl::Procedure*> inlining_;  // procedures being inlined, for recursion
  std::map<const sdl::Procedure*, Ref> procedure_results_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::map<const sdl::CompositeState*, Level*> composite_levels_;
  std::vector<StableState> stable_;     // in order of appearance
  const Level* level_ = nullptr;        // the level whose transition is being translated
  const Level* aggregation_ = nullptr;  // the state aggregation of the state being translated
  std::map<std::pair<const sdl::CompositeState*, std::string>, std::string> entry_places_;
  std::vector<PendingEntry> pending_entries_;
  std::map<std::string, Ref> context_;          // context parameters by folded name
  std::set<const sdl::InputSignal*> reported_;  // unknown inputs, reported once
  std::set<const sdl::State*> refused_blocks_;
  std::map<std::string, std::string> timers_;  // folded name -> BIP base name
  std::map<std::string, std::string> label_places_;
  std::size_t inline_count_ = 0;
  std::string stop_place_;

  // What the translation writes.
  std::set<std::string> used_;
  std::string data_text_, ports_text_, transitions_text_;
  std::vector<std::string> places_;
  /// The internal ports by family: the atom's, and one family per region of a state
  /// aggregation, since two regions' steps may be enabled together and an atom must not offer
  /// one port twice at once.
  std::map<std::string, std::vector<std::string>> branch_ports_;
  std::vector<std::string> port_order_;
  std::size_t place_count_ = 0;
  // Run to completion seen from outside (processes without nested states): a transition keeps
  // its state's place marked and takes the token of `ready_place_` while it runs; origin_of_
  // gives each intermediate place's state (empty for the start transition's).
  std::string ready_place_;
  std::map<std::string, std::string> origin_of_;
  bool is_state_place(const std::string& place) const;
  bool is_return_port(const std::string& port) const;
  bool is_fault_port(const std::string& port) const;
  std::string marking_from(const Step& step, const std::string& to) const;
  std::string marking_to(const Step& step, const std::string& to) const;
  // The faulty package's atom (sdl_fault_atom): faults only, under its own name.
  bool faults_only_ = false;
  std::vector<std::string> notes_, extern_types_, extern_functions_;
  void need_function(const std::string& prototype);
  std::size_t errors_before_ = 0;
  bool quiet_ = false;
};

/// `name` folded for SDL's case-insensitive matching ('-' and '_' alike).
std::string folded(const std::string& name);

/// The name of a signal or timer as SDL spells it and as the signature's BIP identifier does
/// (`clock` and `clock_`) folded alike.
std::string signal_key(const std::string& name);

}  // namespace smcbip::taste2bip::detail
