// The scheduling of one run: computing the items, choosing one (reference random race,
// shared-window shortcut, stochastic race of planned dates, or a picker) and executing it.
#include "engines/detail/scheduler.h"

#include <algorithm>
#include <random>
#include <thread>

namespace smcbip::engines {

namespace {

RuntimeOptions runtime_options(const SimulateOptions& options) {
  RuntimeOptions r;
  r.maximal_progress = !options.disable_maximal_progress;
  r.incremental = options.engine != EngineKind::Reference;
  if (options.engine == EngineKind::Multithread) {
    r.threads =
        options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    r.parallel_min_work = options.parallel_min_work;
  }
  return r;
}

}  // namespace

void Simulator::Shared::prepare(const Externs& externs) {
  problem = build_layout(system, layout);
  this->externs = externs;
  if (problem.empty()) bind_functions(system, this->externs, strings, functions);
  if (problem.empty()) problem = load_custom_distributions(system, custom);
  seed = options.seed ? *options.seed : std::random_device{}();
  stochastic = options.stochastic.value_or(has_stochastic_ports(system));
}

namespace detail {

Scheduler::Scheduler(Simulator::Shared& shared, std::uint64_t run_index, std::ostream& model_output,
                     ItemPicker* picker)
    : shared_(shared),
      options_(shared.options),
      picker_(picker),
      random_(shared.seed, run_index),
      runtime_(shared.model, shared.layout, shared.functions, shared.strings, model_output, random_,
               runtime_options(shared.options)),
      planner_(shared.system, shared.custom, random_, shared.options.unbounded_mean) {}

bool Scheduler::start() {
  if (!runtime_.initialize()) return record_error();
  // The reference engine resumes pending atoms (initial `resume`) before the first step.
  return options_.real_time || runtime_.resume_atoms(0) || record_error();
}

bool Scheduler::restart(std::uint64_t run_index) {
  random_ = RandomStream(shared_.seed, run_index);
  planner_.forget();
  steps_ = 0;
  return start();
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
