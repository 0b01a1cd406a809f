// The multithread scheduler's execution of an interaction: connector `down`s in sequence, then
// the atoms' transitions on the thread pool, with the reference engine's result and error.
#include <algorithm>
#include <exception>
#include <functional>
#include <optional>
#include <string>

#include "engines/api/simulate.h"
#include "engines/semantics/interaction_execution.h"
#include "engines/semantics/parallel_firing.h"

namespace smcbip::engines {

using bipc::ir::Code;
using bipc::ir::Op;
using bipc::ir::Scope;

namespace {

bool code_is_parallel_safe(const Code& code, const BoundFunctions& functions) {
  for (const bipc::ir::Instr& in : code.instrs) {
    if (in.op == Op::Call) {
      const Externs::Function* f = functions.functions[in.index];
      if (f == nullptr || !f->pure) return false;
    }
    // Atom code reads and writes its own atom only; anything else would be shared.
    if ((in.op == Op::Load || in.op == Op::Store) && in.scope != Scope::AtomData &&
        in.scope != Scope::AtomParam && in.scope != Scope::Clock) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::uint8_t> parallel_safe_atom_types(const bipc::ir::System& system,
                                                   const BoundFunctions& functions) {
  std::vector<std::uint8_t> safe;
  for (const bipc::ir::AtomType& type : system.atom_types) {
    bool ok = true;
    auto check = [&](const Code& code) { ok = ok && code_is_parallel_safe(code, functions); };
    for (const bipc::ir::Transition& t : type.transitions) {
      check(t.guard);
      check(t.action);
      if (t.resume) check(t.resume->guard);
    }
    for (const bipc::ir::Invariant& inv : type.invariants) check(inv.guard);
    for (const bipc::ir::AtomPriority& p : type.priorities) check(p.guard);
    safe.push_back(ok ? 1 : 0);
  }
  return safe;
}

std::vector<std::size_t> atom_type_firing_costs(const bipc::ir::System& system) {
  std::vector<std::size_t> costs;
  for (const bipc::ir::AtomType& type : system.atom_types) {
    std::size_t most = 0;
    for (const bipc::ir::Transition& t : type.transitions) {
      const std::size_t resume = t.resume ? t.resume->guard.instrs.size() : 0;
      most = std::max(most, t.guard.instrs.size() + t.action.instrs.size() + resume);
    }
    costs.push_back(most);
  }
  return costs;
}

ParallelFiring::ParallelFiring(const Model& model, const BoundFunctions& functions,
                               const CallContext& main, unsigned threads)
    : pool(threads),
      safe_type(parallel_safe_atom_types(model.system(), functions)),
      cost(atom_type_firing_costs(model.system())) {
  for (unsigned t = 0; t < pool.size(); ++t) {
    evaluators.push_back(std::make_unique<ThreadEvaluator>(model, functions, main));
  }
  seen.assign(model.system().atoms.size(), 0);
}

bool InteractionExecution::fires_in_parallel(Index index) {
  ParallelFiring& p = *parallel_;
  p.ports.clear();
  append_atom_ports(index, p.ports);
  // Parallel firing must pay off and must not be observable: two atoms at least with enough
  // work between them, each of a parallel-safe type, none listed twice (its second firing
  // would see the first).
  bool parallel = p.ports.size() >= 2;
  std::size_t work = 0;
  ++p.execution;
  for (const auto& [atom, port] : p.ports) {
    if (!parallel) break;
    const Index type = system_.atoms[atom].type;
    parallel = p.safe_type[type] && p.seen[atom] != p.execution;
    p.seen[atom] = p.execution;
    work += p.cost[type];
  }
  return parallel && work >= parallel_min_work_;
}

std::size_t InteractionExecution::run_downs(Index index, std::optional<CodeFault>& fault) {
  // A down only writes its own connector's data and the port data of atoms below it, which the
  // atoms fired before it in the reference order never read, so running the downs early changes
  // no value. A down that faults stops the reference engine after the atoms before it: only
  // those fire, and their errors come first.
  std::size_t atoms_so_far = 0;
  std::function<void(Index)> downs = [&](Index value) {
    run_down(value);
    for (const PortValue& pv : connectors_.values()[value].choice) {
      if (pv.from_atom) {
        ++atoms_so_far;
      } else {
        downs(pv.sub);
      }
    }
  };
  try {
    downs(index);
  } catch (const CodeFault& f) {
    fault = f;
    return atoms_so_far;
  }
  return parallel_->ports.size();
}

bool InteractionExecution::fire_ports_in_parallel(std::size_t count) {
  ParallelFiring& p = *parallel_;
  p.fired.assign(count, 0);
  p.errors.resize(count);
  auto fire = [&](std::size_t i, unsigned thread) {
    ThreadEvaluator& t = *p.evaluators[thread];
    const auto [atom, port] = p.ports[i];
    const auto first = state_.data.begin() + static_cast<std::ptrdiff_t>(layout_.atom_data[atom]);
    t.data.assign(first, first + static_cast<std::ptrdiff_t>(
                                     system_.atom_types[system_.atoms[atom].type].data.size()));
    AtomScratch s{*t.eval, p.errors[i], t.data.data(), /*on_worker=*/true, &t.priorities};
    try {
      p.fired[i] = atoms_.fire_port(s, atom, port) ? 1 : 0;
    } catch (const CodeFault& f) {
      s.error = fault_error(system_, f);
    } catch (...) {
      // A user extern declared pure threw: no error channel on a worker thread.
      std::terminate();
    }
    // Also after a failure: the reference engine leaves the writes made before it.
    std::copy(t.data.begin(), t.data.end(), first);
  };
  p.pool.run(count, fire);
  // The scheduler's bookkeeping is shared: the fired atoms are noted once the threads joined.
  for (std::size_t i = 0; i < count; ++i) atoms_.note_changed(p.ports[i].first);
  for (std::size_t i = 0; i < count; ++i) {
    if (!p.fired[i]) {
      error_ = std::move(p.errors[i]);
      return false;
    }
  }
  return true;
}

bool InteractionExecution::execute_in_parallel(Index index) {
  if (!fires_in_parallel(index)) return execute_in_sequence(index);
  // The downs first, in the reference order; then the atoms before the first faulty down.
  std::optional<CodeFault> fault;
  const std::size_t count = run_downs(index, fault);
  if (!fire_ports_in_parallel(count)) return false;
  if (fault) {
    error_ = fault_error(system_, *fault);
    return false;
  }
  return true;
}

}  // namespace smcbip::engines
