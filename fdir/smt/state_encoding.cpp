// The variables of a global state.
#include "fdir/smt/state_encoding.h"

namespace smcbip::fdir {

z3::expr data_constant(z3::context& context, const std::string& name, bipc::ir::ValueKind kind) {
  if (kind == bipc::ir::ValueKind::Bool) return context.bool_const(name.c_str());
  if (kind == bipc::ir::ValueKind::Int) return context.int_const(name.c_str());
  return context.real_const(name.c_str());
}

StateEncoding::StateEncoding(z3::context& context, const bipc::ir::System& system,
                             const PetriNet& net)
    : context_(context), system_(system), net_(net) {
  // Places are prefixed: an atom may have a place and a boolean datum of the same name.
  for (const std::string& name : net.places) {
    places_.push_back(context.bool_const(("@" + name).c_str()));
  }
  for (const bipc::ir::AtomInstance& atom : system.atoms) {
    std::vector<z3::expr>& terms = data_.emplace_back();
    for (const bipc::ir::Data& d : system.atom_types[atom.type].data) {
      const std::string name = system.root_name + "." + atom.path + "." + d.name;
      terms.push_back(data_constant(context, name, d.type.kind));
    }
  }
}

}  // namespace smcbip::fdir
