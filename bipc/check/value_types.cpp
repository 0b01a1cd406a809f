// Value types of the checker: resolving written types, compatibility (int -> float, `refine`)
// and how types are named in messages.
#include "bipc/check/detail/check_context.h"
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

/// Whether extern type `sub` is `super` or refines it, directly or not. The depth bound only
/// guards against a refinement cycle, which check_package_declarations reports and cuts.
bool refines(const ast::ExternTypeDecl* sub, const ast::ExternTypeDecl* super, int depth = 0) {
  if (sub == super) return true;
  if (sub == nullptr || depth > 64) return false;
  for (const ast::TypeRef& parent : sub->refines) {
    if (parent.resolved.kind == ast::ValueType::Kind::Extern &&
        refines(parent.resolved.extern_type, super, depth + 1)) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool assignable(const ast::ValueType& from, const ast::ValueType& to) {
  using Kind = ast::ValueType::Kind;
  // An earlier error has been reported already: accept, so that it is not reported twice.
  if (from.kind == Kind::Error || to.kind == Kind::Error) return true;
  if (from.kind == Kind::Void || to.kind == Kind::Void) return false;
  if (from == to) return true;
  if (from.kind == Kind::Int && to.kind == Kind::Float) return true;
  if (from.kind == Kind::Extern && to.kind == Kind::Extern) {
    return refines(from.extern_type, to.extern_type);
  }
  return false;
}

ast::ValueType resolve_type(ast::TypeRef& type, const ast::Package& package, const Symbols& symbols,
                            Diagnostics& diags) {
  using Kind = ast::ValueType::Kind;
  ast::ValueType resolved;
  if (type.name.parts.empty()) {
    type.resolved = resolved;  // nothing written: a syntax error was reported
    return resolved;
  }
  if (type.name.parts.size() == 1) {
    const std::string& text = type.name.parts.front().text;
    if (text == "int") resolved.kind = Kind::Int;
    if (text == "bool") resolved.kind = Kind::Bool;
    if (text == "float") resolved.kind = Kind::Float;
    if (text == "string") resolved.kind = Kind::String;
  }
  if (resolved.kind == Kind::Error) {
    if (const ast::ExternTypeDecl* decl = symbols.extern_type(package, type.name)) {
      resolved.kind = Kind::Extern;
      resolved.extern_type = decl;
    } else {
      diags.error(type.name.loc(), "unknown data type '" + type.name.text() +
                                       "': expected bool, int, float, string or an extern "
                                       "data type");
    }
  }
  type.resolved = resolved;
  return resolved;
}

bool is_native(const ast::ValueType& type) {
  using Kind = ast::ValueType::Kind;
  return type.kind == Kind::Bool || type.kind == Kind::Int || type.kind == Kind::Float ||
         type.kind == Kind::String;
}

bool is_numeric(const ast::ValueType& type) {
  using Kind = ast::ValueType::Kind;
  return type.kind == Kind::Int || type.kind == Kind::Float;
}

std::string type_name(const ast::ValueType& type) {
  using Kind = ast::ValueType::Kind;
  switch (type.kind) {
    case Kind::Error:
      return "<error>";
    case Kind::Void:
      return "void";
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::String:
      return "string";
    case Kind::Extern:
      return type.extern_type != nullptr ? type.extern_type->name.text : "<extern>";
  }
  return "<error>";
}

std::string type_list(const std::vector<ast::ValueType>& types) {
  std::string text = "(";
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (i > 0) text += ", ";
    text += type_name(types[i]);
  }
  return text + ")";
}

}  // namespace smcbip::bipc::detail
