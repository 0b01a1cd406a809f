// Lowers an atom type: data, clocks, places, ports and their interface, the Petri net,
// priorities and invariants.
#include <string>
#include <unordered_map>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

namespace {

std::vector<ir::Index> indices(const std::vector<int>& resolved) {
  std::vector<ir::Index> result;
  result.reserve(resolved.size());
  for (int i : resolved) result.push_back(i < 0 ? ir::kNone : static_cast<ir::Index>(i));
  return result;
}

ir::Index optional_index(int resolved) {
  return resolved < 0 ? ir::kNone : static_cast<ir::Index>(resolved);
}

/// Builds one atom type; a helper object so that each part is a small function.
class AtomLowering {
 public:
  AtomLowering(const ast::AtomTypeDecl& decl, Lowering& lowering)
      : decl_(decl), lowering_(lowering), code_(lowering) {}

  ir::AtomType run() {
    ir::AtomType t;
    t.name = lowering_.qualified_name(&decl_, decl_.name.text);
    for (const ast::ParamDecl& p : decl_.params) {
      t.params.emplace_back(p.name.text, lowering_.data_type(p.type.resolved));
    }
    for (const ast::DataDecl& d : decl_.data) t.data.push_back(data(d));
    for (const ast::ClockDecl& c : decl_.clocks) {
      t.clocks.push_back({c.name.text, c.unit.value_or(TimeUnit::Millisecond)});
    }
    for (const ast::Ident& place : decl_.places) t.places.push_back(place.text);
    for (const ast::PortDecl& p : decl_.ports) t.ports.push_back(port(p));
    t.interface = interface(t.ports);
    initial(t);
    for (const ast::Transition& tr : decl_.transitions) t.transitions.push_back(transition(tr));
    for (const ast::AtomPriorityDecl& p : decl_.priorities) {
      t.priorities.push_back({p.name.text, optional_index(p.low_index),
                              optional_index(p.high_index),
                              code_.expression(p.guard.get(), ir::ValueKind::Bool)});
    }
    for (const ast::InvariantDecl& inv : decl_.invariants) {
      t.invariants.push_back({inv.name.text, inv.at, indices(inv.place_index),
                              code_.expression(inv.guard.get(), ir::ValueKind::Bool)});
    }
    t.annotations = lower_annotations(decl_.annotations);
    return t;
  }

 private:
  ir::Data data(const ast::DataDecl& d) {
    ir::Data out;
    out.name = d.name.text;
    out.type = lowering_.data_type(d.type.resolved);
    out.exported = d.exported;
    out.initial_value = code_.expression(d.initial_value.get(), out.type.kind);
    return out;
  }

  ir::Port port(const ast::PortDecl& p) {
    ir::Port out;
    out.name = p.name.text;
    if (p.port_type != nullptr) {
      out.type = lowering_.port_type(*p.port_type);
    } else {
      lowering_.internal_error(p.loc, "port type of '" + p.name.text + "'");
    }
    out.data = indices(p.bound_data_index);
    out.exported = p.exported;
    out.is_extern = p.is_extern;
    out.policy = p.policy.value_or(ExternPolicy::Remember);
    if (p.backend_name) out.backend_name = *p.backend_name;
    for (const ast::Annotation& a : p.annotations) {
      if (a.name.text != "stochastic") continue;
      out.stochastic = lower_stochastic(a, decl_, lowering_.package_of(&decl_), lowering_);
    }
    out.annotations = lower_annotations(p.annotations);
    return out;
  }

  /// Individually exported ports stand for themselves; `export port T p, q as e` merges.
  std::vector<ir::InterfacePort> interface(const std::vector<ir::Port>& ports) {
    std::vector<ir::InterfacePort> result;
    std::unordered_map<std::string, std::size_t> merged;
    for (std::size_t i = 0; i < decl_.ports.size(); ++i) {
      const ast::PortDecl& p = decl_.ports[i];
      if (!p.exported) continue;
      const std::string& name = p.merged_as ? p.merged_as->text : p.name.text;
      auto [it, inserted] = merged.try_emplace(name, result.size());
      if (inserted) result.push_back({name, ports[i].type, {}});
      result[it->second].ports.push_back(static_cast<ir::Index>(i));
    }
    return result;
  }

  void initial(ir::AtomType& t) {
    std::unordered_map<std::string, ir::Index> places;
    for (std::size_t i = 0; i < decl_.places.size(); ++i) {
      places.emplace(decl_.places[i].text, static_cast<ir::Index>(i));
    }
    for (const ast::Ident& to : decl_.initial.to) {
      auto found = places.find(to.text);
      if (found == places.end()) {
        lowering_.internal_error(to.loc, "initial place '" + to.text + "'");
        continue;
      }
      t.initial_places.push_back(found->second);
    }
    t.initial_action = code_.block(decl_.initial.action);
    if (decl_.initial.resume) t.initial_resume = resume(*decl_.initial.resume);
  }

  ir::Resume resume(const ast::ResumeClause& r) {
    return {code_.expression(r.guard.get(), ir::ValueKind::Bool)};
  }

  ir::Transition transition(const ast::Transition& tr) {
    ir::Transition out;
    if (tr.port && tr.port_index < 0) lowering_.internal_error(tr.loc, "transition port");
    out.port = optional_index(tr.port_index);
    out.from = indices(tr.from_index);
    out.to = indices(tr.to_index);
    if (out.from.size() != tr.from.size() || out.to.size() != tr.to.size()) {
      lowering_.internal_error(tr.loc, "transition places");
    }
    out.guard = code_.expression(tr.guard.get(), ir::ValueKind::Bool);
    out.action = code_.block(tr.action);
    out.urgency = tr.urgency.value_or(Urgency::Lazy);  // BIP2's default
    if (tr.resume) out.resume = resume(*tr.resume);
    out.annotations = lower_annotations(tr.annotations);
    out.loc = tr.loc;
    return out;
  }

  const ast::AtomTypeDecl& decl_;
  Lowering& lowering_;
  CodeCompiler code_;
};

}  // namespace

ir::Index Lowering::atom_type(const ast::AtomTypeDecl& decl) {
  if (auto found = types_.find(&decl); found != types_.end()) return found->second;
  const auto index = static_cast<ir::Index>(system_.atom_types.size());
  types_[&decl] = index;
  system_.atom_types.emplace_back();
  atom_interface_.emplace_back();
  atom_data_.emplace_back();
  lower_atom_type(decl, index);
  return index;
}

void Lowering::lower_atom_type(const ast::AtomTypeDecl& decl, ir::Index index) {
  ir::AtomType type = AtomLowering(decl, *this).run();
  for (std::size_t i = 0; i < type.interface.size(); ++i) {
    atom_interface_[index].emplace(type.interface[i].name, static_cast<ir::Index>(i));
  }
  for (std::size_t i = 0; i < type.data.size(); ++i) {
    atom_data_[index].emplace(type.data[i].name, static_cast<ir::Index>(i));
  }
  system_.atom_types[index] = std::move(type);
}

}  // namespace smcbip::bipc::lower
