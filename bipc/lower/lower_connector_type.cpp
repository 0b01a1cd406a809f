// Lowers a connector type: port parameters, data, exported port, define tree and interactions.
#include <algorithm>
#include <string>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

namespace {

ir::DefineNode define_node(const ast::PortExpr& e, Lowering& lowering) {
  ir::DefineNode node;
  node.trigger = e.trigger;
  if (e.port) {
    if (e.port_index < 0) lowering.internal_error(e.loc, "define port '" + e.port->text + "'");
    node.port = e.port_index < 0 ? ir::kNone : static_cast<ir::Index>(e.port_index);
    return node;
  }
  for (const ast::PortExpr& child : e.children)
    node.children.push_back(define_node(child, lowering));
  return node;
}

ir::ConnectorType::Resume resume(ast::ConnectorResume r) {
  switch (r) {
    case ast::ConnectorResume::Sync:
      return ir::ConnectorType::Resume::Sync;
    case ast::ConnectorResume::Async:
      return ir::ConnectorType::Resume::Async;
    case ast::ConnectorResume::None:
      break;
  }
  return ir::ConnectorType::Resume::None;
}

ir::InteractionCode interaction(const ast::InteractionDecl& decl, CodeCompiler& code,
                                Lowering& lowering) {
  ir::InteractionCode out;
  if (decl.port_index.size() != decl.ports.size()) {
    lowering.internal_error(decl.loc, "interaction ports");
  }
  for (int i : decl.port_index) {
    if (i >= 0) out.ports.push_back(static_cast<ir::Index>(i));
  }
  std::sort(out.ports.begin(), out.ports.end());
  out.guard = code.expression(decl.guard.get(), ir::ValueKind::Bool);
  out.up = code.block(decl.up);
  out.down = code.block(decl.down);
  out.annotations = lower_annotations(decl.annotations);
  return out;
}

}  // namespace

ir::Index Lowering::connector_type(const ast::ConnectorTypeDecl& decl) {
  if (auto found = types_.find(&decl); found != types_.end()) return found->second;
  const auto index = static_cast<ir::Index>(system_.connector_types.size());
  types_[&decl] = index;
  system_.connector_types.emplace_back();
  lower_connector_type(decl, index);
  return index;
}

void Lowering::lower_connector_type(const ast::ConnectorTypeDecl& decl, ir::Index index) {
  ir::ConnectorType t;
  t.name = qualified_name(&decl, decl.name.text);
  for (const ast::ConnectorTypeDecl::PortParam& p : decl.ports) {
    ir::Index type = 0;
    if (p.port_type != nullptr) {
      type = port_type(*p.port_type);
    } else {
      internal_error(p.loc, "port type of '" + p.name.text + "'");
    }
    t.ports.emplace_back(p.name.text, type);
  }
  CodeCompiler code(*this);
  for (const ast::DataDecl& d : decl.data) {
    ir::Data data{d.name.text, data_type(d.type.resolved), d.exported, {}};
    data.initial_value = code.expression(d.initial_value.get(), data.type.kind);
    t.data.push_back(std::move(data));
  }
  if (decl.export_port) {
    const ast::ConnectorExportPort& xp = *decl.export_port;
    t.export_name = xp.name.text;
    if (xp.port_type != nullptr) {
      t.export_type = port_type(*xp.port_type);
    } else {
      internal_error(xp.loc, "port type of '" + xp.name.text + "'");
    }
    for (int i : xp.bound_data_index) {
      t.export_data.push_back(i < 0 ? ir::kNone : static_cast<ir::Index>(i));
    }
  }
  for (const ast::PortExpr& e : decl.define) t.define.push_back(define_node(e, *this));
  for (const ast::InteractionDecl& i : decl.interactions) {
    t.interactions.push_back(interaction(i, code, *this));
  }
  t.resume = resume(decl.resume);
  t.annotations = lower_annotations(decl.annotations);
  system_.connector_types[index] = std::move(t);
}

}  // namespace smcbip::bipc::lower
