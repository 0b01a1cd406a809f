// Instantiates a checked root compound into the IR: the tree of atom, connector and compound
// instances, with ports resolved through exports and constants folded.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "bipc/bipc.h"
#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc {

namespace lower {
namespace {

// Far beyond any model we know of, low enough that a type nesting that doubles at every level
// is refused before it exhausts memory.
constexpr std::uint64_t kMaxInstances = 16'000'000;
// Instantiation recurses once per level of compound nesting (about a kilobyte of stack each):
// deeper nestings are refused rather than risk overflowing the stack.
constexpr std::uint64_t kMaxNesting = 1000;

std::string join(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "." + name;
}

/// What a name of a compound type denotes: a component or a connector, by declaration index.
struct Member {
  bool is_connector = false;
  std::size_t index = 0;
};
using MemberTable = std::unordered_map<std::string, Member>;

/// A component of a compound instance: an atom instance or a compound instance.
struct Child {
  bool is_atom = true;
  ir::Index index = ir::kNone;
};

/// One compound instance under construction: its parameters and children, which give meaning
/// to the names of its priority guards, component arguments and port references.
class CompoundScope final : public InstanceBindings {
 public:
  CompoundScope(const ast::CompoundTypeDecl& type, ir::Index compound,
                std::vector<ir::Value> params, const MemberTable& members, const ir::System& system,
                const Lowering& lowering)
      : type(type),
        compound(compound),
        params(std::move(params)),
        members(members),
        system_(system),
        lowering_(lowering) {}

  const ir::Value* compound_param(int index) const override {
    if (index < 0 || static_cast<std::size_t>(index) >= params.size()) return nullptr;
    return &params[static_cast<std::size_t>(index)];
  }

  std::optional<std::pair<ir::Index, ir::Index>> component_data(
      int component, const std::string& member) const override {
    if (component < 0 || static_cast<std::size_t>(component) >= children.size())
      return std::nullopt;
    const Child& child = children[static_cast<std::size_t>(component)];
    if (child.index == ir::kNone) return std::nullopt;
    if (child.is_atom) {
      auto slot = lowering_.atom_data(system_.atoms[child.index].type, member);
      if (!slot) return std::nullopt;
      return std::make_pair(child.index, *slot);
    }
    const auto& exported = system_.compounds[child.index].exported_data;
    auto found = exported.find(member);
    if (found == exported.end()) return std::nullopt;
    return found->second;
  }

  const ast::CompoundTypeDecl& type;
  const ir::Index compound;
  const std::vector<ir::Value> params;
  const MemberTable& members;
  std::vector<Child> children;        // per component declaration
  std::vector<ir::Index> connectors;  // per connector declaration

 private:
  const ir::System& system_;
  const Lowering& lowering_;
};

class Instantiator {
 public:
  Instantiator(const LoadedModel& model, ir::System& system, Diagnostics& diags)
      : model_(model), lowering_(model, system, diags), system_(system), diags_(diags) {}

  void run(const ast::ComponentDecl& root) {
    if (root.compound_type == nullptr) {
      lowering_.internal_error(root.loc, "root compound type");
      return;
    }
    const ast::CompoundTypeDecl& type = *root.compound_type;
    const Extent extent = extent_of(type);
    if (extent.instances > kMaxInstances) {
      diags_.error(root.loc, "the root has more than " + std::to_string(kMaxInstances) +
                                 " component and connector instances; not supported");
      return;
    }
    if (extent.nesting > kMaxNesting) {
      diags_.error(root.loc, "the root nests compound instances more than " +
                                 std::to_string(kMaxNesting) + " levels deep; not supported");
      return;
    }
    system_.root_type = lowering_.qualified_name(&type, type.name.text);
    std::vector<ir::Value> params = arguments(root, type.params, nullptr, system_.root_name);
    build_compound(type, "", ir::kNone, std::move(params), root);
    collect_cpp();
    check_instances(system_, connector_locs_, diags_);
  }

 private:
  ir::Index build_compound(const ast::CompoundTypeDecl& type, const std::string& path,
                           ir::Index parent, std::vector<ir::Value> params,
                           const ast::ComponentDecl& decl) {
    if (!building_.insert(&type).second) {
      diags_.error(decl.loc, "compound type '" + type.name.text + "' contains itself");
      return ir::kNone;
    }
    const auto index = static_cast<ir::Index>(system_.compounds.size());
    ir::CompoundInstance instance;
    instance.path = path;
    instance.type = lowering_.qualified_name(&type, type.name.text);
    instance.parent = parent;
    instance.annotations = lower_annotations(decl.annotations);
    system_.compounds.push_back(std::move(instance));

    CompoundScope scope(type, index, std::move(params), members(type), system_, lowering_);
    build_components(scope, path);
    create_connectors(scope, path);
    bind_connectors(scope);
    build_priorities(scope);
    build_exports(scope);
    building_.erase(&type);
    return index;
  }

  void build_components(CompoundScope& scope, const std::string& path) {
    for (const ast::ComponentDecl& decl : scope.type.components) {
      const std::string child_path = join(path, decl.name.text);
      Child child;
      if (decl.atom_type != nullptr) {
        ir::AtomInstance atom;
        atom.path = child_path;
        atom.params = arguments(decl, decl.atom_type->params, &scope, child_path);
        atom.type = lowering_.atom_type(*decl.atom_type);
        atom.parent = scope.compound;
        atom.annotations = lower_annotations(decl.annotations);
        child.index = static_cast<ir::Index>(system_.atoms.size());
        system_.atoms.push_back(std::move(atom));
        system_.compounds[scope.compound].atoms.push_back(child.index);
      } else if (decl.compound_type != nullptr) {
        std::vector<ir::Value> params =
            arguments(decl, decl.compound_type->params, &scope, child_path);
        child.is_atom = false;
        child.index = build_compound(*decl.compound_type, child_path, scope.compound,
                                     std::move(params), decl);
        if (child.index != ir::kNone)
          system_.compounds[scope.compound].compounds.push_back(child.index);
      } else {
        lowering_.internal_error(decl.loc, "type of component '" + decl.name.text + "'");
      }
      scope.children.push_back(child);
    }
  }

  // All connectors of a compound get their index before any is bound: a hierarchical
  // connector may name one declared after it.
  void create_connectors(CompoundScope& scope, const std::string& path) {
    for (const ast::ConnectorDecl& decl : scope.type.connectors) {
      ir::ConnectorInstance connector;
      connector.path = join(path, decl.name.text);
      if (decl.connector_type != nullptr) {
        connector.type = lowering_.connector_type(*decl.connector_type);
      } else {
        lowering_.internal_error(decl.loc, "type of connector '" + decl.name.text + "'");
        connector.type = ir::kNone;
      }
      connector.parent = scope.compound;
      connector.bound.resize(decl.ports.size());
      connector.bound_through_compound.resize(decl.ports.size(), false);
      for (const ast::QualifiedName& port : decl.ports)
        connector.bound_names.push_back(port.text());
      connector.annotations = lower_annotations(decl.annotations);
      const auto index = static_cast<ir::Index>(system_.connectors.size());
      system_.connectors.push_back(std::move(connector));
      connector_locs_.push_back(decl.loc);
      system_.compounds[scope.compound].connectors.push_back(index);
      scope.connectors.push_back(index);
    }
  }

  void bind_connectors(const CompoundScope& scope) {
    for (std::size_t j = 0; j < scope.type.connectors.size(); ++j) {
      const ast::ConnectorDecl& decl = scope.type.connectors[j];
      const ir::Index k = scope.connectors[j];
      for (std::size_t i = 0; i < decl.ports.size(); ++i) {
        std::vector<ir::PortRef> refs = resolve_port(scope, decl.ports[i]);
        for (const ir::PortRef& ref : refs) {
          if (ref.kind == ir::PortRef::Kind::Connector) bind_export(ref.instance, k, decl.ports[i]);
        }
        auto member = decl.ports[i].parts.empty() ? scope.members.end()
                                                  : scope.members.find(decl.ports[i].parts[0].text);
        system_.connectors[k].bound_through_compound[i] =
            member != scope.members.end() && !member->second.is_connector &&
            !scope.children[member->second.index].is_atom;
        system_.connectors[k].bound[i] = std::move(refs);
      }
    }
  }

  /// Records who binds a connector's exported port. Several connectors may (the conformance
  /// models `maximal_progress` and `hierarchy` do), as several may bind one atom port.
  void bind_export(ir::Index sub, ir::Index by, const ast::QualifiedName& where) {
    ir::ConnectorInstance& bound = system_.connectors[sub];
    if (sub == by) {
      diags_.error(where.loc(), "connector '" + bound.path + "' binds its own exported port");
      return;
    }
    if (bound.bound_by == ir::kNone) bound.bound_by = by;
    if (bound.bound_by_all.empty() || bound.bound_by_all.back() != by) {
      bound.bound_by_all.push_back(by);
    }
  }

  /// The ports `component.port` or `connector.port` stands for, through exports.
  std::vector<ir::PortRef> resolve_port(const CompoundScope& scope, const ast::QualifiedName& ref) {
    auto member =
        ref.parts.size() == 2 ? scope.members.find(ref.parts[0].text) : scope.members.end();
    if (member == scope.members.end()) {
      lowering_.internal_error(ref.loc(), "port reference '" + ref.text() + "'");
      return {};
    }
    const std::string& port = ref.parts[1].text;
    if (member->second.is_connector)
      return connector_port(scope.connectors[member->second.index], ref);
    const Child& child = scope.children[member->second.index];
    if (child.index == ir::kNone) return {};  // already reported
    std::vector<ir::PortRef> refs;
    if (child.is_atom) {
      const ir::Index type = system_.atoms[child.index].type;
      if (auto ip = lowering_.atom_interface_port(type, port)) {
        for (ir::Index p : system_.atom_types[type].interface[*ip].ports) {
          refs.push_back({ir::PortRef::Kind::Atom, child.index, p});
        }
        return refs;
      }
    } else {
      const auto& exported = system_.compounds[child.index].exported_ports;
      if (auto found = exported.find(port); found != exported.end()) return found->second;
    }
    lowering_.internal_error(ref.loc(), "port reference '" + ref.text() + "'");
    return refs;
  }

  std::vector<ir::PortRef> connector_port(ir::Index k, const ast::QualifiedName& ref) {
    const ir::Index type = system_.connectors[k].type;
    if (type >= system_.connector_types.size()) return {};  // already reported
    const auto& name = system_.connector_types[type].export_name;
    if (!name || *name != ref.parts[1].text) {
      lowering_.internal_error(ref.loc(), "port reference '" + ref.text() + "'");
      return {};
    }
    return {{ir::PortRef::Kind::Connector, k, 0}};
  }

  void build_priorities(CompoundScope& scope) {
    CodeCompiler code(lowering_, &scope);
    for (const ast::CompoundPriorityDecl& decl : scope.type.priorities) {
      ir::Priority priority;
      priority.name = decl.name.text;
      priority.low = side(scope, decl.low);
      priority.high = side(scope, decl.high);
      priority.guard = code.expression(decl.guard.get(), ir::ValueKind::Bool);
      system_.compounds[scope.compound].priorities.push_back(std::move(priority));
    }
  }

  ir::PatternSide side(const CompoundScope& scope, const ast::InteractionPattern& pattern) {
    ir::PatternSide side;
    side.all_ports = pattern.all_ports;
    if (pattern.connector) {
      const int index = pattern.connector_index;
      if (index < 0 || static_cast<std::size_t>(index) >= scope.connectors.size()) {
        lowering_.internal_error(pattern.loc, "connector '" + pattern.connector->text + "'");
        return side;
      }
      side.connector = scope.connectors[static_cast<std::size_t>(index)];
    }
    for (const ast::QualifiedName& port : pattern.ports) {
      std::vector<ir::PortRef> refs = resolve_port(scope, port);
      side.ports.insert(side.ports.end(), refs.begin(), refs.end());
    }
    return side;
  }

  void build_exports(const CompoundScope& scope) {
    std::map<std::string, std::vector<ir::PortRef>> ports;
    for (const ast::PortExportDecl& decl : scope.type.port_exports) {
      std::vector<ir::PortRef>& refs = ports[decl.name.text];
      for (const ast::QualifiedName& port : decl.ports) {
        std::vector<ir::PortRef> resolved = resolve_port(scope, port);
        refs.insert(refs.end(), resolved.begin(), resolved.end());
      }
    }
    std::map<std::string, std::pair<ir::Index, ir::Index>> data;
    for (const ast::DataExportDecl& decl : scope.type.data_exports) {
      const ast::QualifiedName& ref = decl.data;
      auto member =
          ref.parts.size() == 2 ? scope.members.find(ref.parts[0].text) : scope.members.end();
      std::optional<std::pair<ir::Index, ir::Index>> slot;
      if (member != scope.members.end() && !member->second.is_connector) {
        slot = scope.component_data(static_cast<int>(member->second.index), ref.parts[1].text);
      }
      if (slot) {
        data[decl.name.text] = *slot;
      } else {
        lowering_.internal_error(ref.loc(), "exported data '" + ref.text() + "'");
      }
    }
    ir::CompoundInstance& compound = system_.compounds[scope.compound];
    compound.exported_ports = std::move(ports);
    compound.exported_data = std::move(data);
  }

  /// Folds component arguments to constants, converted to the parameter types.
  std::vector<ir::Value> arguments(const ast::ComponentDecl& decl,
                                   const std::vector<ast::ParamDecl>& params,
                                   const InstanceBindings* bindings, const std::string& path) {
    std::vector<ir::Value> values;
    if (decl.args.size() != params.size()) {
      lowering_.internal_error(decl.loc, "argument count of '" + path + "'");
    }
    CodeCompiler code(lowering_, bindings);
    for (std::size_t i = 0; i < params.size(); ++i) {
      ir::Value value;
      value.kind = value_kind(params[i].type.resolved);
      if (i < decl.args.size() && decl.args[i]) {
        ir::Code c = code.expression(decl.args[i].get(), value.kind);
        if (auto v = evaluate_constant(c.instrs, 0, c.instrs.size(), system_.strings)) {
          value = convert_value(std::move(*v), value.kind);
        } else {
          diags_.error(decl.args[i]->loc, "argument " + std::to_string(i + 1) + " of '" + path +
                                              "' is not a compile-time constant");
        }
      }
      values.push_back(std::move(value));
    }
    return values;
  }

  const MemberTable& members(const ast::CompoundTypeDecl& type) {
    auto [it, inserted] = members_.try_emplace(&type);
    if (inserted) {
      for (std::size_t i = 0; i < type.components.size(); ++i) {
        it->second.try_emplace(type.components[i].name.text, Member{false, i});
      }
      for (std::size_t i = 0; i < type.connectors.size(); ++i) {
        it->second.try_emplace(type.connectors[i].name.text, Member{true, i});
      }
    }
    return it->second;
  }

  /// The size of a compound type's instance tree: its instances, saturated above the limit,
  /// and its depth in compound levels. Computed per type so that an exponential nesting is
  /// refused without expanding it.
  struct Extent {
    std::uint64_t instances = 0;
    std::uint64_t nesting = 0;
  };
  Extent extent_of(const ast::CompoundTypeDecl& type) {
    if (auto found = extents_.find(&type); found != extents_.end()) return found->second;
    extents_[&type] = Extent{};  // a self-containing type is reported when it is built
    Extent extent{1 + type.connectors.size(), 1};
    for (const ast::ComponentDecl& c : type.components) {
      if (c.compound_type == nullptr) {
        extent.instances += 1;
        continue;
      }
      const Extent inner = extent_of(*c.compound_type);
      extent.instances += inner.instances;
      extent.nesting = std::max(extent.nesting, inner.nesting + 1);
      if (extent.instances > kMaxInstances || extent.nesting > kMaxNesting) break;
    }
    extent.instances = std::min(extent.instances, kMaxInstances + 1);
    extents_[&type] = extent;
    return extent;
  }

  /// `@cpp(src="a.cpp,b.cpp", include="x.hpp")` of every package, each file once.
  void collect_cpp() {
    std::unordered_set<std::string> seen;
    for (const auto& package : model_.packages) {
      if (!package) continue;
      for (const ast::Annotation& a : package->annotations) {
        if (a.name.text != "cpp") continue;
        for (const ast::AnnotationParam& p : a.params) {
          if (!p.value) continue;
          auto* list = p.key.text == "src"       ? &system_.cpp_sources
                       : p.key.text == "include" ? &system_.cpp_includes
                                                 : nullptr;
          if (list == nullptr) continue;
          const std::filesystem::path folder = std::filesystem::path(package->path).parent_path();
          for (const std::string& written : split_list(*p.value)) {
            // Extern sources are named relative to the package file, as the Verimag compiler
            // reads them; headers are found through the package folders.
            const std::string file = list == &system_.cpp_sources && !written.empty() &&
                                             std::filesystem::path(written).is_relative()
                                         ? (folder / written).lexically_normal().string()
                                         : written;
            if (seen.insert(p.key.text + ":" + file).second) list->push_back(file);
          }
          const std::string dir = folder.empty() ? "." : folder.string();
          if (seen.insert("dir:" + dir).second) system_.cpp_include_dirs.push_back(dir);
        }
      }
    }
  }

  static std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::string::size_type start = 0;
    while (start <= text.size()) {
      auto comma = text.find(',', start);
      if (comma == std::string::npos) comma = text.size();
      const std::string item = text.substr(start, comma - start);
      const auto first = item.find_first_not_of(" \t");
      if (first != std::string::npos) {
        items.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
      }
      start = comma + 1;
    }
    return items;
  }

  const LoadedModel& model_;
  Lowering lowering_;
  ir::System& system_;
  Diagnostics& diags_;
  std::unordered_map<const ast::CompoundTypeDecl*, MemberTable> members_;
  std::unordered_map<const ast::CompoundTypeDecl*, Extent> extents_;
  std::unordered_set<const ast::CompoundTypeDecl*> building_;  // against self-containment
  std::vector<Location> connector_locs_;                       // per connector instance
};

}  // namespace
}  // namespace lower

std::optional<ir::System> instantiate(const LoadedModel& model, const ast::ComponentDecl& root,
                                      Diagnostics& diags) {
  ir::System system;
  const std::size_t errors_before = diags.error_count();
  lower::Instantiator(model, system, diags).run(root);
  if (diags.error_count() > errors_before) return std::nullopt;
  ir::number_code(system);
  system.source_files = model.files.paths;
  return system;
}

}  // namespace smcbip::bipc
