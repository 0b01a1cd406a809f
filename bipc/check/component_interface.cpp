// The interface of a component as its enclosing compound sees it: exported ports (merged exports
// count once, under their `as` name) and exported data, for atom and compound types alike.
#include <map>
#include <utility>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

// Nested compounds are followed this deep at most: a safety net, since interface_of does not
// enter a type that contains itself (an error the compound check reports).
constexpr int kMaxDepth = 64;

const ast::PortTypeDecl* port_type_of(const ast::PortDecl& port, const ast::AtomTypeDecl& atom,
                                      const Symbols& symbols) {
  if (port.port_type != nullptr) return port.port_type;
  const ast::Package* package = symbols.package_of(&atom);
  return package != nullptr ? symbols.port_type(*package, port.type) : nullptr;
}

void add_port(ComponentInterface& interface, const std::string& name,
              const ast::PortTypeDecl* type) {
  for (const ComponentInterface::PortEntry& entry : interface.ports) {
    if (entry.name == name) return;  // another port of the same merged export
  }
  interface.ports.push_back({name, type});
}

ComponentInterface atom_interface(const ast::AtomTypeDecl& atom, const Symbols& symbols) {
  ComponentInterface interface;
  for (const ast::PortDecl& port : atom.ports) {
    if (!port.exported) continue;
    const std::string& name = port.merged_as ? port.merged_as->text : port.name.text;
    add_port(interface, name, port_type_of(port, atom, symbols));
  }
  for (const ast::DataDecl& data : atom.data) {
    if (data.exported) interface.data.push_back({data.name.text, data.type.resolved});
  }
  return interface;
}

/// Computes interfaces through nested compounds. A compound re-exporting several ports of one
/// inner component asks for that component's interface once per port: results are kept per
/// type and depth, so a chain of such compounds costs linear, not exponential, time.
class InterfaceFinder {
 public:
  explicit InterfaceFinder(const Symbols& symbols) : symbols_(symbols) {}

  ComponentInterface of_types(const ast::AtomTypeDecl* atom, const ast::CompoundTypeDecl* compound,
                              int depth) {
    if (depth > kMaxDepth) return {};
    if (atom != nullptr) return atom_interface(*atom, symbols_);
    if (compound == nullptr) return {};
    const auto key = std::make_pair(compound, depth);
    if (auto found = known_.find(key); found != known_.end()) return found->second;
    ComponentInterface interface = compound_interface(*compound, depth);
    known_.emplace(key, interface);
    return interface;
  }

 private:
  /// The inner component named `name`, with its types resolved by the compound check or, when
  /// that has not run yet, looked up here.
  ComponentInterface inner_interface(const ast::CompoundTypeDecl& compound, const std::string& name,
                                     int depth) {
    const int c = index_of(compound.components, name);
    if (c < 0) return {};
    const ast::ComponentDecl& component = compound.components[c];
    const ast::AtomTypeDecl* atom = component.atom_type;
    const ast::CompoundTypeDecl* inner = component.compound_type;
    const ast::Package* package = symbols_.package_of(&compound);
    if (atom == nullptr && inner == nullptr && package != nullptr) {
      atom = symbols_.atom_type(*package, component.type);
      if (atom == nullptr) inner = symbols_.compound_type(*package, component.type);
    }
    return of_types(atom, inner, depth + 1);
  }

  /// The port type of `inner.port` inside `compound`: a component's port or a connector's export.
  const ast::PortTypeDecl* referenced_port_type(const ast::CompoundTypeDecl& compound,
                                                const ast::QualifiedName& ref, int depth) {
    if (ref.parts.size() != 2) return nullptr;
    const std::string& inner = ref.parts[0].text;
    const std::string& port = ref.parts[1].text;
    if (const int k = index_of(compound.connectors, inner); k >= 0) {
      const ast::ConnectorDecl& connector = compound.connectors[k];
      const ast::ConnectorTypeDecl* type = connector.connector_type;
      const ast::Package* package = symbols_.package_of(&compound);
      if (type == nullptr && package != nullptr)
        type = symbols_.connector_type(*package, connector.type);
      if (type == nullptr || !type->export_port || type->export_port->name.text != port)
        return nullptr;
      return type->export_port->port_type;
    }
    for (const auto& entry : inner_interface(compound, inner, depth).ports) {
      if (entry.name == port) return entry.type;
    }
    return nullptr;
  }

  ComponentInterface compound_interface(const ast::CompoundTypeDecl& compound, int depth) {
    ComponentInterface interface;
    for (const ast::PortExportDecl& exported : compound.port_exports) {
      const ast::PortTypeDecl* type = nullptr;
      for (const ast::QualifiedName& ref : exported.ports) {
        type = referenced_port_type(compound, ref, depth);
        if (type != nullptr) break;
      }
      add_port(interface, exported.name.text, type);
    }
    for (const ast::DataExportDecl& exported : compound.data_exports) {
      ast::ValueType type;
      if (exported.data.parts.size() == 2) {
        const std::string& member = exported.data.parts[1].text;
        for (const auto& entry :
             inner_interface(compound, exported.data.parts[0].text, depth).data) {
          if (entry.name == member) type = entry.type;
        }
      }
      interface.data.push_back({exported.name.text, type});
    }
    return interface;
  }

  const Symbols& symbols_;
  std::map<std::pair<const ast::CompoundTypeDecl*, int>, ComponentInterface> known_;
};

}  // namespace

ComponentInterface interface_of(const ast::ComponentDecl& component, const Symbols& symbols) {
  // Below a type whose instantiation ends, every nested type ends too: checking once suffices.
  if (component.compound_type != nullptr &&
      instantiation_never_ends(*component.compound_type, symbols)) {
    return {};
  }
  return interface_of_ending(component, symbols);
}

ComponentInterface interface_of_ending(const ast::ComponentDecl& component,
                                       const Symbols& symbols) {
  return InterfaceFinder(symbols).of_types(component.atom_type, component.compound_type, 0);
}

}  // namespace smcbip::bipc::detail
