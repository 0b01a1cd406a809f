// The enabledness of interactions over a global state's variables.
#include "fdir/prove/deadlock_predicate.h"

namespace smcbip::fdir {

namespace {

/// The transition `t` of `atom` may fire: its input places are marked and its guard holds.
z3::expr transition_enabled(const StateEncoding& state, CodeEncoder& encoder, Index atom, Index t) {
  const bipc::ir::System& system = state.system();
  const bipc::ir::AtomType& type = system.atom_types[system.atoms[atom].type];
  const bipc::ir::Transition& tr = type.transitions[t];
  z3::expr out = state.context().bool_val(true);
  for (Index p : tr.from) out = out && state.place(atom, p);
  CodeFrame frame{state.data(atom), &system.atoms[atom].params, {}};
  return out && encoder.expression(tr.guard, frame);
}

/// A connector's port parameter `param` reads datum `arg` of its port type: the atom's datum
/// when the parameter binds one atom port.
std::optional<z3::expr> port_datum(const StateEncoding& state, Index connector, Index param,
                                   Index arg) {
  const bipc::ir::System& system = state.system();
  const auto& bound = system.connectors[connector].bound;
  if (param >= bound.size() || bound[param].size() != 1) return std::nullopt;
  const bipc::ir::PortRef& ref = bound[param].front();
  if (ref.kind != bipc::ir::PortRef::Kind::Atom) return std::nullopt;
  const bipc::ir::AtomType& type = system.atom_types[system.atoms[ref.instance].type];
  if (arg >= type.ports[ref.port].data.size()) return std::nullopt;
  const Index slot = type.ports[ref.port].data[arg];
  const z3::expr& datum = state.data(ref.instance)[slot];
  if (!datum.is_int() && !datum.is_bool()) return std::nullopt;
  return datum;
}

}  // namespace

z3::expr interaction_enabled(const StateEncoding& state, CodeEncoder& encoder, Index k) {
  const NetInteraction& interaction = state.net().interactions[k];
  z3::context& c = state.context();
  z3::expr out = c.bool_val(true);
  for (const std::vector<PortOffer>& offers : interaction.ports) {
    z3::expr any = c.bool_val(false);
    for (const PortOffer& offer : offers) {
      for (Index t : offer.transitions)
        any = any || transition_enabled(state, encoder, offer.atom, t);
    }
    out = out && any;
  }
  if (interaction.code >= 0) {
    const bipc::ir::System& system = state.system();
    const Index connector = interaction.connector;
    const auto& type = system.connector_types[system.connectors[connector].type];
    CodeFrame frame;
    frame.port_data = [&state, connector](Index param, Index arg) {
      return port_datum(state, connector, param, arg);
    };
    out = out && encoder.expression(type.interactions[interaction.code].guard, frame);
  }
  return out;
}

z3::expr deadlock_predicate(const StateEncoding& state, CodeEncoder& encoder) {
  z3::expr_vector none(state.context());
  for (Index k = 0; k < state.net().interactions.size(); ++k) {
    none.push_back(!interaction_enabled(state, encoder, k));
  }
  return z3::mk_and(none);
}

}  // namespace smcbip::fdir
