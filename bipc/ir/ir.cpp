// Small helpers over the IR's names and kinds, shared by its writers and the engines.
#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

std::string last_component(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

const char* value_kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::Void:
      return "void";
    case ValueKind::Bool:
      return "bool";
    case ValueKind::Int:
      return "int";
    case ValueKind::Float:
      return "float";
    case ValueKind::String:
      return "string";
    case ValueKind::Extern:
      return "extern";
  }
  return "?";
}

namespace {

void number_atom_type(AtomType& type, std::uint32_t& next) {
  for (Data& d : type.data) d.initial_value.id = next++;
  type.initial_action.id = next++;
  if (type.initial_resume) type.initial_resume->guard.id = next++;
  for (Port& port : type.ports) {
    if (!port.stochastic) continue;
    for (Code& param : port.stochastic->params) param.id = next++;
  }
  for (Transition& t : type.transitions) {
    t.guard.id = next++;
    t.action.id = next++;
    if (t.resume) t.resume->guard.id = next++;
  }
  for (AtomPriority& p : type.priorities) p.guard.id = next++;
  for (Invariant& inv : type.invariants) inv.guard.id = next++;
}

}  // namespace

void number_code(System& system) {
  std::uint32_t next = 0;
  for (AtomType& type : system.atom_types) number_atom_type(type, next);
  for (ConnectorType& type : system.connector_types) {
    for (Data& d : type.data) d.initial_value.id = next++;
    for (InteractionCode& code : type.interactions) {
      code.guard.id = next++;
      code.up.id = next++;
      code.down.id = next++;
    }
  }
  for (CompoundInstance& compound : system.compounds) {
    for (Priority& p : compound.priorities) p.guard.id = next++;
  }
  system.code_count = next;
}

}  // namespace smcbip::bipc::ir
