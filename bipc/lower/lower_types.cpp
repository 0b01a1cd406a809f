// The type tables of a lowering run: extern types, functions, port types, constants, strings.
#include <string>

#include "bipc/lower/detail/lowering.h"

namespace smcbip::bipc::lower {

Lowering::Lowering(const LoadedModel& model, ir::System& system, Diagnostics& diags)
    : system_(system), diags_(diags) {
  index_packages(model);
}

// The AST does not link declarations to their package; one pass over all of them does, so
// that qualified names cost a hash lookup.
void Lowering::index_packages(const LoadedModel& model) {
  for (const auto& package : model.packages) {
    if (!package) continue;
    const ast::Package* p = package.get();
    for (const auto& d : p->consts) package_of_[&d] = p;
    for (const auto& d : p->extern_types) package_of_[&d] = p;
    for (const auto& d : p->extern_functions) package_of_[&d] = p;
    for (const auto& d : p->port_types) package_of_[&d] = p;
    for (const auto& d : p->atom_types) package_of_[&d] = p;
    for (const auto& d : p->connector_types) package_of_[&d] = p;
    for (const auto& d : p->compound_types) package_of_[&d] = p;
  }
}

const ast::Package* Lowering::package_of(const void* decl) const {
  auto found = package_of_.find(decl);
  return found == package_of_.end() ? nullptr : found->second;
}

std::string Lowering::qualified_name(const void* decl, const std::string& name) const {
  const ast::Package* package = package_of(decl);
  if (package == nullptr || package->name.parts.empty()) return name;
  return package->name.text() + "." + name;
}

void Lowering::internal_error(Location at, const std::string& what) {
  diags_.error(at, "internal error: " + what + " (the checker should have resolved it)");
}

ir::Index Lowering::string(const std::string& text) {
  auto [it, inserted] = strings_.try_emplace(text, static_cast<ir::Index>(system_.strings.size()));
  if (inserted) system_.strings.push_back(text);
  return it->second;
}

ir::Index Lowering::site(Location at) {
  // Each instance's code is compiled again: its sites are shared, not repeated.
  auto [it, inserted] = sites_.try_emplace(std::tuple(at.file, at.line, at.column),
                                           static_cast<ir::Index>(system_.sites.size()));
  if (inserted) system_.sites.push_back(at);
  return it->second;
}

ir::DataType Lowering::data_type(const ast::ValueType& type) {
  ir::DataType result;
  result.kind = value_kind(type);
  if (result.kind == ir::ValueKind::Extern && type.extern_type != nullptr) {
    result.extern_type = extern_type(*type.extern_type);
  }
  return result;
}

ir::Index Lowering::extern_type(const ast::ExternTypeDecl& decl) {
  if (auto found = types_.find(&decl); found != types_.end()) return found->second;
  const auto index = static_cast<ir::Index>(system_.extern_types.size());
  types_[&decl] = index;  // before the refined types, so that a refinement cycle terminates
  system_.extern_types.emplace_back();
  ir::ExternType type;
  type.name = qualified_name(&decl, decl.name.text);
  type.backend_name = decl.backend_name ? *decl.backend_name : decl.name.text;
  for (const ast::TypeRef& refined : decl.refines) {
    if (refined.resolved.extern_type != nullptr) {
      type.refines.push_back(extern_type(*refined.resolved.extern_type));
    }
  }
  system_.extern_types[index] = std::move(type);
  return index;
}

ir::Index Lowering::function(const ast::ExternFunctionDecl& decl) {
  if (auto found = types_.find(&decl); found != types_.end()) return found->second;
  ir::ExternFunction f;
  f.name = decl.name.text;  // the C++ name: extern functions are not package-qualified
  f.is_operator = decl.is_operator;
  if (decl.result) f.result = data_type(decl.result->resolved);
  for (const ast::ParamDecl& param : decl.params) {
    f.params.push_back(data_type(param.type.resolved));
    f.const_params.push_back(param.type.is_const);
  }
  const auto index = static_cast<ir::Index>(system_.functions.size());
  system_.functions.push_back(std::move(f));
  types_[&decl] = index;
  return index;
}

ir::Index Lowering::port_type(const ast::PortTypeDecl& decl) {
  if (auto found = types_.find(&decl); found != types_.end()) return found->second;
  ir::PortType type;
  type.name = qualified_name(&decl, decl.name.text);
  for (const ast::ParamDecl& param : decl.params) {
    type.params.emplace_back(param.name.text, data_type(param.type.resolved));
  }
  const auto index = static_cast<ir::Index>(system_.port_types.size());
  system_.port_types.push_back(std::move(type));
  types_[&decl] = index;
  return index;
}

std::optional<ir::Value> Lowering::constant(const ast::ConstDataDecl& decl) {
  if (auto found = constants_.find(&decl); found != constants_.end()) return found->second;
  if (!evaluating_.insert(&decl).second) {
    diags_.error(decl.loc, "constant '" + decl.name.text + "' is defined in terms of itself");
    constants_[&decl] = std::nullopt;
    return std::nullopt;
  }
  // Constants live outside instances; a throw-away code buffer evaluates the initialiser.
  const ir::ValueKind kind = value_kind(decl.type.resolved);
  ir::Code code = CodeCompiler(*this).expression(decl.value.get(), kind);
  std::optional<ir::Value> value =
      evaluate_constant(code.instrs, 0, code.instrs.size(), system_.strings);
  evaluating_.erase(&decl);
  if (value) {
    value = convert_value(std::move(*value), kind);
  } else if (!constants_.count(&decl)) {
    diags_.error(decl.loc, "the value of constant '" + decl.name.text +
                               "' cannot be computed at compile time");
  }
  constants_[&decl] = value;
  return value;
}

std::optional<ir::Index> Lowering::atom_interface_port(ir::Index atom_type,
                                                       const std::string& name) const {
  if (atom_type >= atom_interface_.size()) return std::nullopt;
  const NameIndex& names = atom_interface_[atom_type];
  auto found = names.find(name);
  if (found == names.end()) return std::nullopt;
  return found->second;
}

std::optional<ir::Index> Lowering::atom_data(ir::Index atom_type, const std::string& name) const {
  if (atom_type >= atom_data_.size()) return std::nullopt;
  const NameIndex& names = atom_data_[atom_type];
  auto found = names.find(name);
  if (found == names.end()) return std::nullopt;
  return found->second;
}

std::vector<ir::Annotation> lower_annotations(const ast::Annotations& annotations) {
  std::vector<ir::Annotation> result;
  result.reserve(annotations.size());
  for (const ast::Annotation& a : annotations) {
    ir::Annotation out;
    out.name = a.name.text;
    out.loc = a.loc;
    for (const ast::AnnotationParam& p : a.params) out.params.emplace_back(p.key.text, p.value);
    result.push_back(std::move(out));
  }
  return result;
}

}  // namespace smcbip::bipc::lower
