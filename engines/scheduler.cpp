// The scheduling of one run: computing the items, choosing one (reference random race,
// shared-window shortcut, stochastic race of planned dates, or a picker) and executing it.
#include "engines/detail/scheduler.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <random>

#include "engines/engine.h"
#include "engines/semantics/interpreted_steps.h"

namespace smcbip::engines {

namespace {

/// Whether code of the system reads a clock or calls an extern function, except the
/// parameters of @stochastic ports (they only draw dates): then the places and data alone no
/// longer decide what is enabled and what the actions write.
bool reads_clocks_or_calls(const bipc::ir::System& system) {
  bool found = false;
  bipc::ir::for_each_code(system, [&](const bipc::ir::Code& code, bipc::ir::CodeUse use) {
    if (use == bipc::ir::CodeUse::Value) return;
    for (const bipc::ir::Instr& instr : code.instrs) {
      if (instr.op == bipc::ir::Op::Call ||
          (instr.op == bipc::ir::Op::Load && instr.scope == bipc::ir::Scope::Clock)) {
        found = true;
      }
    }
  });
  return found;
}

}  // namespace

void Simulator::Shared::prepare(const Externs& externs) {
  problem = build_layout(system, layout);
  this->externs = externs;
  if (problem.empty()) bind_functions(system, this->externs, strings, functions);
  if (problem.empty()) problem = load_custom_distributions(system, custom);
  seed = options.seed ? *options.seed : std::random_device{}();
  stochastic = options.stochastic.value_or(has_stochastic_ports(system));
  absorbing_checks = options.stop_absorbing && problem.empty() && layout.extern_ports.empty() &&
                     !reads_clocks_or_calls(system);
  same_start = problem.empty() && layout.extern_ports.empty() && system.functions.empty();
}

namespace detail {

RunParts::RunParts(Simulator::Shared& shared, std::ostream& model_output)
    : output(&model_output),
      random(shared.seed, 0),
      runtime(shared.model, shared.layout, shared.functions, shared.strings, model_output, random,
              engine_of(shared.options.engine).runtime_options(shared.options)),
      planner(shared.system, shared.custom, random, shared.options.unbounded_mean) {}

namespace {

/// The spare parts of `shared` that write to `output`, or new ones. Searched from the back:
/// the last run's are there, and taking them shifts nothing.
std::unique_ptr<RunParts> take_parts(Simulator::Shared& shared, std::ostream& output) {
  auto& spare = shared.spare_parts;
  const auto it = std::find_if(spare.rbegin(), spare.rend(),
                               [&](const auto& parts) { return parts->output == &output; });
  if (it == spare.rend()) return std::make_unique<RunParts>(shared, output);
  std::unique_ptr<RunParts> parts = std::move(*it);
  spare.erase(std::next(it).base());
  return parts;
}

}  // namespace

Scheduler::Scheduler(Simulator::Shared& shared, std::uint64_t run_index, std::ostream& model_output,
                     ItemPicker* picker)
    : shared_(shared),
      options_(shared.options),
      picker_(picker),
      parts_(take_parts(shared, model_output)),
      random_(parts_->random),
      shared_window_(parts_->shared_window),
      runtime_(parts_->runtime),
      planner_(parts_->planner),
      dates_(parts_->dates),
      planner_problem_(parts_->planner_problem) {
  // As restart(): start() initialises the runtime whatever run it made before.
  renew(run_index);
}

Scheduler::~Scheduler() {
  // A few are enough: one simulator makes one run at a time.
  constexpr std::size_t kMaxSpare = 4;
  if (shared_.spare_parts.size() < kMaxSpare) shared_.spare_parts.push_back(std::move(parts_));
}

bool Scheduler::start() {
  if (!runtime_.initialize()) return record_error();
  // The reference engine resumes pending atoms (initial `resume`) before the first step.
  return options_.real_time || runtime_.resume_atoms(0) || record_error();
}

bool Scheduler::start_state() {
  if (parts_->initial_state) {
    // Assigned in place: the state's buffers keep their size from run to run.
    assign_state(runtime_.state(), *parts_->initial_state);
    return true;
  }
  if (!start()) return false;
  if (shared_.same_start && !options_.real_time) parts_->initial_state = runtime_.state();
  return true;
}

bool Scheduler::started_from_kept_state() const { return parts_->initial_state.has_value(); }

bool Scheduler::restart(std::uint64_t run_index) {
  renew(run_index);
  return start();
}

void Scheduler::renew(std::uint64_t run_index) {
  random_ = RandomStream(shared_.seed, run_index);
  planner_.forget();
  steps_ = 0;
  idle_step_ = false;
  checks_absorbing_ = shared_.checks_absorbing_from_start();
}

CompiledSteps* Scheduler::compiled_steps() {
  if (!parts_->compiled_steps_made) {
    // The model's generated path, else the same path interpreting the atoms' transitions.
    parts_->compiled_steps = runtime_.code().make_steps(shared_.system, shared_.layout);
    if (!parts_->compiled_steps) {
      parts_->compiled_steps =
          make_interpreted_steps(runtime_.code(), shared_.system, shared_.layout);
    }
    parts_->compiled_steps_made = true;
  }
  return parts_->compiled_steps.get();
}

void Scheduler::remember_discrete_state() {
  const RunState& state = runtime_.state();
  copy_over(state.data, parts_->data_before);
  copy_over(state.marking, parts_->marking_before);
  copy_over(state.resume_pending, parts_->resume_before);
}

bool Scheduler::discrete_state_kept(const RunState& state) const {
  // Bytes, as the explorer keys states: equal strings have equal ids.
  return state.marking == parts_->marking_before && state.resume_pending == parts_->resume_before &&
         std::equal(state.data.begin(), state.data.end(), parts_->data_before.begin(),
                    parts_->data_before.end(),
                    [](Val a, Val b) { return std::memcmp(&a, &b, sizeof(Val)) == 0; });
}

bool Scheduler::absorbing(bool& failed) {
  parts_->absorbing_probe = runtime_.state();
  const std::size_t count = runtime_.item_count();
  const TimeValue now = parts_->absorbing_probe.now;
  bool kept = true;
  for (std::size_t k = 0; k < count && kept; ++k) {
    // Each item from the probed state: restore recomputes the offers that execute consumed.
    if (k > 0 && (!runtime_.restore(parts_->absorbing_probe) || !runtime_.compute_items())) {
      kept = false;
      break;
    }
    remember_discrete_state();
    kept = runtime_.execute(runtime_.item(k), now) && runtime_.resume_atoms(now) &&
           discrete_state_kept(runtime_.state());
  }
  failed = !runtime_.restore(parts_->absorbing_probe) || !runtime_.compute_items();
  if (failed) record_error();
  return kept && !failed;
}

bool Scheduler::record_error() {
  error_ = runtime_.error();
  return false;
}

const Decision& Scheduler::fail() {
  record_error();
  return end(RunEnd::Error, error_.code);
}

const Decision& Scheduler::end(RunEnd end, int code) {
  decision_.kind = Decision::Kind::End;
  decision_.end = end;
  decision_.code = code;
  return decision_;
}

const Decision& Scheduler::receive(TimeValue arrival) {
  decision_.kind = Decision::Kind::Receive;
  decision_.date = arrival;
  return decision_;
}

}  // namespace detail

}  // namespace smcbip::engines
