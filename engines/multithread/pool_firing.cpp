// The multithread engine's execution of an interaction: connector `down`s in sequence, then
// the atoms' transitions on the thread pool, with the reference engine's result and error.
#include "engines/multithread/pool_firing.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <optional>
#include <string>

#include "engines/api/simulate.h"

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

PoolFiring::PoolFiring(const Model& model, const BoundFunctions& functions, const CallContext& main,
                       const RuntimeOptions& options)
    : pool_(options.threads),
      min_work_(options.parallel_min_work),
      safe_type_(parallel_safe_atom_types(model.system(), functions)),
      cost_(atom_type_firing_costs(model.system())) {
  for (unsigned t = 0; t < pool_.size(); ++t) {
    evaluators_.push_back(std::make_unique<ThreadEvaluator>(model, functions, main));
  }
  seen_.assign(model.system().atoms.size(), 0);
}

std::unique_ptr<ParallelFiring> make_pool_firing(const Model& model,
                                                 const BoundFunctions& functions,
                                                 const CallContext& main,
                                                 const RuntimeOptions& options) {
  return std::make_unique<PoolFiring>(model, functions, main, options);
}

bool PoolFiring::fires_in_parallel(const InteractionExecution& execution, Index index) {
  ports_.clear();
  execution.append_atom_ports(index, ports_);
  // Parallel firing must pay off and must not be observable: two atoms at least with enough
  // work between them, each of a parallel-safe type, none listed twice (its second firing
  // would see the first).
  bool parallel = ports_.size() >= 2;
  std::size_t work = 0;
  ++execution_;
  for (const auto& [atom, port] : ports_) {
    if (!parallel) break;
    const Index type = execution.system().atoms[atom].type;
    parallel = safe_type_[type] && seen_[atom] != execution_;
    seen_[atom] = execution_;
    work += cost_[type];
  }
  return parallel && work >= min_work_;
}

std::size_t PoolFiring::run_downs(InteractionExecution& execution, Index index,
                                  std::optional<CodeFault>& fault) {
  // A down only writes its own connector's data and the port data of atoms below it, which the
  // atoms fired before it in the reference order never read, so running the downs early changes
  // no value. A down that faults stops the reference engine after the atoms before it: only
  // those fire, and their errors come first.
  std::size_t atoms_so_far = 0;
  std::function<void(Index)> downs = [&](Index value) {
    execution.run_down(value);
    for (const PortValue& pv : execution.values()[value].choice) {
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
  return ports_.size();
}

bool PoolFiring::fire_ports(InteractionExecution& execution, std::size_t count) {
  const bipc::ir::System& system = execution.system();
  const Layout& layout = execution.layout();
  std::vector<Val>& data = execution.state().data;
  AtomFiring& atoms = execution.atoms();
  fired_.assign(count, 0);
  errors_.resize(count);
  auto fire = [&](std::size_t i, unsigned thread) {
    ThreadEvaluator& t = *evaluators_[thread];
    const auto [atom, port] = ports_[i];
    const auto first = data.begin() + static_cast<std::ptrdiff_t>(layout.atom_data[atom]);
    t.data.assign(first, first + static_cast<std::ptrdiff_t>(
                                     system.atom_types[system.atoms[atom].type].data.size()));
    AtomScratch s{*t.eval, errors_[i], t.data.data(), /*on_worker=*/true, &t.priorities};
    try {
      fired_[i] = atoms.fire_port(s, atom, port) ? 1 : 0;
    } catch (const CodeFault& f) {
      s.error = fault_error(system, f);
    } catch (...) {
      // A user extern declared pure threw: no error channel on a worker thread.
      std::terminate();
    }
    // Also after a failure: the reference engine leaves the writes made before it.
    std::copy(t.data.begin(), t.data.end(), first);
  };
  pool_.run(count, fire);
  // The scheduler's bookkeeping is shared: the fired atoms are noted once the threads joined.
  for (std::size_t i = 0; i < count; ++i) atoms.note_changed(ports_[i].first);
  for (std::size_t i = 0; i < count; ++i) {
    if (!fired_[i]) {
      execution.error() = std::move(errors_[i]);
      return false;
    }
  }
  return true;
}

std::optional<bool> PoolFiring::execute(InteractionExecution& execution, Index index) {
  if (!fires_in_parallel(execution, index)) return std::nullopt;
  // The downs first, in the reference order; then the atoms before the first faulty down.
  std::optional<CodeFault> fault;
  const std::size_t count = run_downs(execution, index, fault);
  if (!fire_ports(execution, count)) return false;
  if (fault) {
    execution.error() = fault_error(execution.system(), *fault);
    return false;
  }
  return true;
}

}  // namespace smcbip::engines
