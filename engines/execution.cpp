// A run driven by its host: the scheduler's decisions carried out one step at a time, a decision
// due after the host's date kept for later, host writes and host-fed extern ports.
#include "engines/api/execution.h"

#include <algorithm>
#include <vector>

#include "engines/detail/scheduler.h"

namespace smcbip::engines {

namespace {

using detail::Decision;
using detail::step_info;

/// The events the host fed to one extern port, oldest first, in a ring of slots allocated once.
class FedQueue {
 public:
  FedQueue(AtomPort port, std::size_t arity, std::size_t capacity)
      : port_(port), arity_(arity), dates_(capacity), values_(capacity * arity) {}

  AtomPort port() const { return port_; }
  std::size_t arity() const { return arity_; }
  /// False when the queue is full.
  bool push(TimeValue date, std::span<const Val> values) {
    if (size_ == dates_.size()) return false;
    const std::size_t slot = (first_ + size_) % dates_.size();
    dates_[slot] = date;
    std::copy(values.begin(), values.end(),
              values_.begin() + static_cast<std::ptrdiff_t>(slot * arity_));
    ++size_;
    return true;
  }
  /// The oldest event into `event` (its buffer reused); false when the queue is empty.
  bool pop(ExternEvent& event) {
    if (size_ == 0) return false;
    event.time = dates_[first_];
    const auto values = values_.begin() + static_cast<std::ptrdiff_t>(first_ * arity_);
    event.values.assign(values, values + static_cast<std::ptrdiff_t>(arity_));
    first_ = (first_ + 1) % dates_.size();
    --size_;
    return true;
  }

 private:
  AtomPort port_;
  std::size_t arity_;
  std::vector<TimeValue> dates_;
  std::vector<Val> values_;  // arity_ per slot
  std::size_t first_ = 0, size_ = 0;
};

/// The source of a host-fed port: its queue. An empty queue reads as the end of the events;
/// the execution wakes the port up when the host feeds it again.
class FedSource final : public ExternPortSource {
 public:
  explicit FedSource(FedQueue& queue) : queue_(queue) {}
  std::optional<ExternEvent> next(TimeValue now) override {
    ExternEvent event;
    if (!pull(now, event)) return std::nullopt;
    return event;
  }
  bool pull(TimeValue /*now*/, ExternEvent& event) override { return queue_.pop(event); }

 private:
  FedQueue& queue_;
};

}  // namespace

struct Execution::State {
  Simulator::Shared shared;
  std::vector<FedQueue> fed;  // never resized after construction: sources refer to them
  ExternPortFactory fed_factory;
  std::optional<detail::Scheduler> scheduler;
  std::ostream& model_output;
  RunObserver* observer = nullptr;
  bool pending = false;  // the scheduler's decision is not carried out yet
  bool started = false;
  bool over = false;  // an Error or Stopped end: nothing more happens
  RunResult result;
  std::string ended_message;  // result's message after its place in the model (StepOutcome)

  State(const Model& model, const SimulateOptions& options, std::ostream& out)
      : shared(model, options), model_output(out) {}
  State(std::unique_ptr<InterpretedModel> model, const SimulateOptions& options, std::ostream& out)
      : shared(std::move(model), options), model_output(out) {}

  void prepare(const Externs& externs, std::size_t fed_capacity);
  Runtime& runtime() { return scheduler->runtime(); }
  StateView view() const {
    return {shared.system, shared.layout, scheduler->runtime().state(), shared.strings};
  }
  StepOutcome ended_outcome() const {
    StepOutcome outcome;
    outcome.ended = true;
    outcome.end = result.end;
    outcome.code = result.code;
    outcome.message = ended_message;
    return outcome;
  }
  /// Ends the run as `end` with the scheduler's error, or none; tells the observer.
  StepOutcome end(RunEnd end, bool error) {
    const ModelError none;
    const ModelError& why = error ? scheduler->error() : none;
    result = {why.code, end, scheduler->steps(), why.message, why.where};
    ended_message = located_message(why.where, why.message);
    over = error || end == RunEnd::Stopped;
    if (observer) observer->finish(result.end, result.code, ended_message);
    return ended_outcome();
  }
  /// The pending decision, deciding it when there is none; an End decision ends the run (once).
  const Decision& decision() {
    if (pending) return scheduler->decision();
    pending = true;
    const Decision& d = scheduler->decide();
    if (d.kind == Decision::Kind::End) end(d.end, d.end == RunEnd::Error);
    return d;
  }
  /// Carries out the pending Fire or Receive decision; a step is observed. Outcome: stepped,
  /// ended, or neither (events received).
  StepOutcome perform() {
    const Decision& d = scheduler->decision();
    pending = false;
    StepOutcome outcome;
    if (d.kind == Decision::Kind::Fire) {
      outcome.info = step_info(d.item, runtime(), scheduler->steps() + 1, d.date);
    }
    if (!scheduler->perform(d)) return end(RunEnd::Error, true);
    if (d.kind == Decision::Kind::Receive) return outcome;
    outcome.stepped = true;
    if (observer && !observer->observe(outcome.info, view())) {
      const StepInfo info = outcome.info;
      outcome = end(RunEnd::Stopped, false);
      outcome.stepped = true;
      outcome.info = info;
    }
    return outcome;
  }
  /// A write or feed changed what comes next: the decision is made again.
  void drop_decision() {
    if (!over) pending = false;
  }
};

void Execution::State::prepare(const Externs& externs, std::size_t fed_capacity) {
  const SimulateOptions& options = shared.options;
  shared.prepare(externs);
  if (!shared.problem.empty()) return;
  if (options.real_time || options.interactive || options.explore) {
    shared.problem =
        "a host-driven execution runs in simulated time, the host choosing the dates (no "
        "--real-time, --interactive or --explore)";
    return;
  }
  const bipc::ir::System& system = shared.system;
  for (const auto& [atom, port] : shared.layout.extern_ports) {
    const bipc::ir::Port& p = system.atom_types[system.atoms[atom].type].ports[port];
    const ExternPortFactory*& factory = shared.functions.port_classes[p.backend_name];
    if (factory != nullptr && factory != &fed_factory) continue;
    factory = &fed_factory;
    fed.emplace_back(AtomPort{atom, port}, p.data.size(), fed_capacity);
  }
  fed_factory = [this](const std::string& atom_path, const std::string& port_name) {
    const bipc::ir::System& system = shared.system;
    for (FedQueue& queue : fed) {
      const bipc::ir::AtomInstance& atom = system.atoms[queue.port().atom];
      if (atom.path == atom_path &&
          system.atom_types[atom.type].ports[queue.port().port].name == port_name) {
        return std::unique_ptr<ExternPortSource>(std::make_unique<FedSource>(queue));
      }
    }
    return std::unique_ptr<ExternPortSource>();
  };
  scheduler.emplace(shared, options.run_index, model_output);
}

Execution::Execution(const Model& model, const SimulateOptions& options, const Externs& externs,
                     std::ostream& model_output, std::size_t fed_capacity)
    : state_(std::make_unique<State>(model, options, model_output)) {
  state_->prepare(externs, fed_capacity);
}

Execution::Execution(const bipc::ir::System& system, const SimulateOptions& options,
                     const Externs& externs, std::ostream& model_output, std::size_t fed_capacity)
    : state_(std::make_unique<State>(std::make_unique<InterpretedModel>(system), options,
                                     model_output)) {
  state_->prepare(externs, fed_capacity);
}

Execution::~Execution() = default;

const std::string& Execution::problem() const { return state_->shared.problem; }
std::uint64_t Execution::seed() const { return state_->shared.seed; }

bool Execution::start(std::optional<std::uint64_t> run_index) {
  State& s = *state_;
  s.started = true;
  s.pending = false;
  s.over = false;
  s.result = {};
  if (!s.shared.problem.empty()) {
    s.result = {kInputError, RunEnd::Error, 0, s.shared.problem, {}};
    s.ended_message = s.shared.problem;
    s.over = true;
    return false;
  }
  if (!s.scheduler->restart(run_index.value_or(s.shared.options.run_index))) {
    s.end(RunEnd::Error, true);
    return false;
  }
  if (s.observer && !s.observer->observe(StepInfo{}, s.view())) {
    s.end(RunEnd::Stopped, false);
    return false;
  }
  return true;
}

StepOutcome Execution::step() {
  State& s = *state_;
  if (!s.started) start();
  if (s.over) return s.ended_outcome();
  for (;;) {
    if (s.decision().kind == Decision::Kind::End) return s.ended_outcome();
    const StepOutcome outcome = s.perform();
    if (outcome.stepped || outcome.ended) return outcome;
  }
}

StepOutcome Execution::run_until(TimeValue t) {
  State& s = *state_;
  if (!s.started) start();
  StepOutcome last;
  while (!s.over) {
    const Decision& d = s.decision();
    if (d.kind == Decision::Kind::End) {
      StepOutcome outcome = s.ended_outcome();
      outcome.stepped = last.stepped;
      outcome.info = last.info;
      return outcome;
    }
    if (d.date > t) {
      // Time passes to t, where nothing is due: the decision stays the run's next.
      RunState& state = s.runtime().state();
      state.now = std::max(state.now, t);
      return last;
    }
    const StepOutcome outcome = s.perform();
    if (outcome.stepped) last = outcome;
    if (outcome.ended) return outcome;
  }
  StepOutcome outcome = s.ended_outcome();
  outcome.stepped = last.stepped;
  outcome.info = last.info;
  return outcome;
}

std::optional<TimeValue> Execution::next_date() {
  State& s = *state_;
  if (!s.started) start();
  if (s.over) return std::nullopt;
  const Decision& d = s.decision();
  if (d.kind == Decision::Kind::End) return std::nullopt;
  return d.date;
}

TimeValue Execution::now() const {
  return state_->scheduler ? state_->scheduler->runtime().state().now : 0;
}

std::uint64_t Execution::steps() const {
  return state_->scheduler ? state_->scheduler->steps() : 0;
}

const RunResult& Execution::result() const { return state_->result; }

StateView Execution::state() const { return state_->view(); }

void Execution::set_observer(RunObserver* observer) { state_->observer = observer; }

namespace {

/// The atom named `atom` (`ROOT.a.b`) and the index of its type's `member` (data or ports)
/// named `name`, or nullopt.
template <class Named>
std::optional<std::pair<bipc::ir::Index, bipc::ir::Index>> find_in_atom(
    const Simulator::Shared& shared, std::string_view atom,
    std::vector<Named> bipc::ir::AtomType::*member, std::string_view name) {
  const std::vector<std::string>& atoms = shared.layout.atom_names;
  const auto named = std::find(atoms.begin(), atoms.end(), atom);
  if (named == atoms.end()) return std::nullopt;
  const auto a = static_cast<bipc::ir::Index>(named - atoms.begin());
  const std::vector<Named>& items = shared.system.atom_types[shared.system.atoms[a].type].*member;
  for (bipc::ir::Index i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return std::pair{a, i};
  }
  return std::nullopt;
}

}  // namespace

std::optional<DataSlot> Execution::find_data(std::string_view atom, std::string_view data) const {
  const auto found = find_in_atom(state_->shared, atom, &bipc::ir::AtomType::data, data);
  if (!found) return std::nullopt;
  return DataSlot{found->first, found->second};
}

std::optional<AtomPort> Execution::find_port(std::string_view atom, std::string_view port) const {
  const auto found = find_in_atom(state_->shared, atom, &bipc::ir::AtomType::ports, port);
  if (!found) return std::nullopt;
  return AtomPort{found->first, found->second};
}

Val Execution::read(bipc::ir::Index atom, bipc::ir::Index slot) const {
  return state_->view().data(atom, slot);
}

bool Execution::write(bipc::ir::Index atom, bipc::ir::Index slot, Val value) {
  State& s = *state_;
  if (!s.started || s.over) return false;
  if (!s.runtime().write_data(atom, slot, value)) {
    s.pending = false;
    s.scheduler->record_error();
    s.end(RunEnd::Error, true);
    return false;
  }
  s.drop_decision();
  return true;
}

bool Execution::feed(bipc::ir::Index atom, bipc::ir::Index port, TimeValue date,
                     std::span<const Val> values) {
  State& s = *state_;
  const auto queue = std::find_if(s.fed.begin(), s.fed.end(), [&](const FedQueue& q) {
    return q.port().atom == atom && q.port().port == port;
  });
  if (queue == s.fed.end() || values.size() != queue->arity() || !queue->push(date, values)) {
    return false;
  }
  if (s.started && !s.over) {
    s.runtime().wake_extern_port(atom, port);
    s.drop_decision();
  }
  return true;
}

}  // namespace smcbip::engines
