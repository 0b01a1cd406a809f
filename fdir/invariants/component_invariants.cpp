// Forward post-condition iteration per atom, with quantifier elimination by Z3.
#include "fdir/invariants/component_invariants.h"

#include <set>

namespace smcbip::fdir {

namespace {

using bipc::ir::ValueKind;

bool has_quantifier(const z3::expr& e, std::set<unsigned>& seen) {
  if (!seen.insert(e.id()).second) return false;
  if (e.is_quantifier()) return true;
  if (!e.is_app()) return false;
  for (unsigned k = 0; k < e.num_args(); ++k) {
    if (has_quantifier(e.arg(k), seen)) return true;
  }
  return false;
}

bool tracked(ValueKind kind) { return kind == ValueKind::Int || kind == ValueKind::Bool; }

std::string template_key(const bipc::ir::AtomInstance& atom) {
  std::string key = std::to_string(atom.type);
  for (const bipc::ir::Value& v : atom.params) {
    key += "," + std::to_string(static_cast<int>(v.kind)) + ":" + std::to_string(v.i) + ":" +
           std::to_string(v.b) + ":" + std::to_string(v.f) + ":" + v.s;
  }
  return key;
}

}  // namespace

z3::expr eliminate(z3::context& context, const z3::expr_vector& vars, const z3::expr& body) {
  if (vars.empty()) return body.simplify();
  z3::goal goal(context);
  goal.add(z3::exists(vars, body));
  const z3::tactic qe = z3::tactic(context, "qe") & z3::tactic(context, "simplify");
  const z3::apply_result result = qe(goal);
  z3::expr out = context.bool_val(false);
  for (unsigned k = 0; k < result.size(); ++k) out = out || result[k].as_expr();
  std::set<unsigned> seen;
  if (has_quantifier(out, seen)) return context.bool_val(true);
  return out.simplify();
}

z3::expr exactly_one(z3::context& context, const std::vector<z3::expr>& places) {
  z3::expr_vector all(context);
  for (const z3::expr& p : places) all.push_back(p);
  if (places.empty()) return context.bool_val(true);
  std::vector<int> ones(places.size(), 1);
  return z3::pbeq(all, ones.data(), 1);
}

struct ComponentInvariants::Template {
  const bipc::ir::AtomType* type = nullptr;
  std::vector<z3::expr> places, data, primes;
  z3::expr_vector tracked_data, tracked_primes;
};

namespace {

/// Whether some interaction's `down` of connector type `type` stores into port parameter
/// `param`'s data.
bool down_writes(const bipc::ir::ConnectorType& type, Index param) {
  for (const bipc::ir::InteractionCode& code : type.interactions) {
    if (writes_port(code.down, param)) return true;
  }
  return false;
}

}  // namespace

ComponentInvariants::ComponentInvariants(const StateEncoding& state, CodeEncoder& encoder,
                                         unsigned iterations)
    : state_(state), encoder_(encoder), iterations_(iterations) {
  const bipc::ir::System& system = state.system();
  for (const bipc::ir::AtomInstance& atom : system.atoms) {
    written_.emplace_back(system.atom_types[atom.type].ports.size(), 0);
  }
  for (const bipc::ir::ConnectorInstance& c : system.connectors) {
    const bipc::ir::ConnectorType& type = system.connector_types[c.type];
    for (Index param = 0; param < c.bound.size(); ++param) {
      if (!down_writes(type, param)) continue;
      for (const bipc::ir::PortRef& ref : c.bound[param]) {
        if (ref.kind == bipc::ir::PortRef::Kind::Atom) written_[ref.instance][ref.port] = 1;
      }
    }
  }
}

std::vector<z3::expr> ComponentInvariants::initial_data(const Template& t, Index atom) {
  z3::context& c = state_.context();
  CodeFrame frame;
  frame.params = &state_.system().atoms[atom].params;
  for (const bipc::ir::Data& d : t.type->data) {
    frame.data.push_back(d.type.kind == ValueKind::Bool  ? c.bool_val(false)
                         : d.type.kind == ValueKind::Int ? c.int_val(0)
                                                         : encoder_.unknown(d.type.kind));
  }
  for (std::size_t k = 0; k < t.type->data.size(); ++k) {
    const bipc::ir::Data& d = t.type->data[k];
    if (!d.initial_value.empty()) frame.data[k] = encoder_.expression(d.initial_value, frame);
  }
  encoder_.statement(t.type->initial_action, frame);
  return frame.data;
}

z3::expr ComponentInvariants::post(const Template& t, Index atom, const bipc::ir::Transition& tr,
                                   const z3::expr& before) {
  z3::context& c = state_.context();
  encoder_.clear_fresh();
  CodeFrame frame;
  frame.params = &state_.system().atoms[atom].params;
  frame.data = t.data;
  const z3::expr guard = encoder_.expression(tr.guard, frame);
  if (tr.port != bipc::ir::kNone && written_[atom][tr.port]) {
    for (Index slot : t.type->ports[tr.port].data) {
      frame.data[slot] = encoder_.unknown(t.type->data[slot].type.kind);
    }
  }
  encoder_.statement(tr.action, frame);
  // Every value the engines hold, before and after, and every unknown one, is a 64-bit integer.
  z3::expr body = before && guard;
  for (std::size_t k = 0; k < t.data.size(); ++k) {
    if (!tracked(t.type->data[k].type.kind)) continue;
    body = body && t.primes[k] == frame.data[k] && int64_bounds(t.data[k]) &&
           int64_bounds(t.primes[k]);
  }
  z3::expr_vector vars = encoder_.fresh();
  for (const z3::expr& v : vars) body = body && int64_bounds(v);
  for (const z3::expr& x : t.tracked_data) vars.push_back(x);
  z3::expr after = eliminate(c, vars, body);
  z3::expr_vector from = t.tracked_primes, to = t.tracked_data;
  return after.substitute(from, to);
}

std::vector<z3::expr> ComponentInvariants::iterate(const Template& t, Index atom,
                                                   const std::vector<z3::expr>& init) {
  z3::context& c = state_.context();
  std::vector<z3::expr> phi(t.places.size(), c.bool_val(true));
  for (unsigned round = 0; round < iterations_; ++round) {
    std::vector<z3::expr> next = init;
    for (const bipc::ir::Transition& tr : t.type->transitions) {
      const Index from = tr.from.front(), to = tr.to.front();
      next[to] = next[to] || post(t, atom, tr, phi[from]);
    }
    bool same = true;
    for (std::size_t l = 0; l < phi.size(); ++l) {
      next[l] = next[l].simplify();
      same = same && z3::eq(next[l], phi[l]);
    }
    phi = std::move(next);
    if (same) break;
  }
  return phi;
}

ComponentInvariants::Template ComponentInvariants::compute(Index atom) {
  z3::context& c = state_.context();
  Template t{&state_.system().atom_types[state_.system().atoms[atom].type],
             {},
             {},
             {},
             z3::expr_vector(c),
             z3::expr_vector(c)};
  for (std::size_t l = 0; l < t.type->places.size(); ++l) {
    t.places.push_back(c.bool_const(("at!" + std::to_string(l)).c_str()));
  }
  for (std::size_t k = 0; k < t.type->data.size(); ++k) {
    const ValueKind kind = t.type->data[k].type.kind;
    t.data.push_back(data_constant(c, "x!" + std::to_string(k), kind));
    t.primes.push_back(data_constant(c, "x'!" + std::to_string(k), kind));
    if (tracked(kind)) {
      t.tracked_data.push_back(t.data.back());
      t.tracked_primes.push_back(t.primes.back());
    }
  }
  return t;
}

z3::expr ComponentInvariants::of_atom(Index atom) {
  z3::context& c = state_.context();
  const bipc::ir::AtomInstance& instance = state_.system().atoms[atom];
  const bipc::ir::AtomType& type = state_.system().atom_types[instance.type];
  if (!bipc::ir::is_state_machine(type)) return c.bool_val(true);
  const Template t = compute(atom);
  std::string key = template_key(instance);
  for (std::uint8_t w : written_[atom]) key += w ? 'w' : '-';
  auto cached = cache_.find(key);
  if (cached == cache_.end()) {
    z3::expr invariant = exactly_one(c, t.places);
    if (!t.tracked_data.empty()) {
      encoder_.clear_fresh();
      const std::vector<z3::expr> values = initial_data(t, atom);
      z3::expr start = c.bool_val(true);
      for (std::size_t k = 0; k < values.size(); ++k) {
        if (tracked(type.data[k].type.kind)) start = start && t.data[k] == values[k];
      }
      start = eliminate(c, encoder_.fresh(), start);
      std::vector<z3::expr> init(t.places.size(), c.bool_val(false));
      init[type.initial_places.front()] = start;
      const std::vector<z3::expr> phi = iterate(t, atom, init);
      for (std::size_t l = 0; l < phi.size(); ++l)
        invariant = invariant && z3::implies(t.places[l], phi[l]);
    }
    cached = cache_.emplace(key, invariant.simplify()).first;
  }
  if (!t.tracked_data.empty()) ++data_invariants_;
  z3::expr_vector from(c), to(c);
  for (std::size_t l = 0; l < t.places.size(); ++l) {
    from.push_back(t.places[l]);
    to.push_back(state_.place(atom, static_cast<Index>(l)));
  }
  for (std::size_t k = 0; k < t.data.size(); ++k) {
    from.push_back(t.data[k]);
    to.push_back(state_.data(atom)[k]);
  }
  return cached->second.substitute(from, to);
}

z3::expr ComponentInvariants::all() {
  z3::expr_vector all(state_.context());
  for (Index a = 0; a < state_.system().atoms.size(); ++a) all.push_back(of_atom(a));
  return z3::mk_and(all);
}

}  // namespace smcbip::fdir
