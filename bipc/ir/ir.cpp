// Small helpers over the IR's names and kinds, shared by its writers and the engines.
#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

std::string last_component(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

bool is_state_machine(const AtomType& type) {
  if (type.initial_places.size() != 1) return false;
  for (const Transition& t : type.transitions) {
    if (t.from.size() != 1 || t.to.size() != 1) return false;
  }
  return true;
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

void number_code(System& system) {
  std::uint32_t next = 0;
  for_each_code(system, [&](Code& code, CodeUse) { code.id = next++; });
  system.code_count = next;
}

}  // namespace smcbip::bipc::ir
