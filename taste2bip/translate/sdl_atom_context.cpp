// The function's context parameters as the SDL reads them (`<function>_ctxt.name`): data
// `ctxt_<name>` holding the interface view's value from the start.
#include <cctype>
#include <cstdlib>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

bool is_number(const std::string& text, bool real) {
  if (text.empty()) return false;
  char* end = nullptr;
  if (real) {
    (void)std::strtod(text.c_str(), &end);
  } else {
    (void)std::strtoll(text.c_str(), &end, 10);
  }
  return end == text.c_str() + text.size();
}

}  // namespace

/// The BIP text of a scalar context value as the view writes it (ASN.1 value notation: 42, -1.5,
/// TRUE, an enumerant), or nullopt.
std::optional<std::string> Translator::context_value(const Leaf& leaf, const std::string& text) {
  if (leaf.type == "bool" && (folded(text) == "true" || folded(text) == "false")) {
    return folded(text);
  }
  if (leaf.type == "int" && is_number(text, false)) return text;
  if (leaf.type == "float" && is_number(text, true)) {
    return text.find_first_of(".eE") == std::string::npos ? text + ".0" : text;
  }
  if (leaf.type == "int" && leaf.asn1_type != nullptr) {
    for (const asn1::Enumerant& e : leaf.asn1_type->enumerants) {
      if (folded(e.name) == folded(text)) return std::to_string(e.value);
    }
  }
  return std::nullopt;
}

void Translator::declare_context() {
  for (const ContextValue& c : function_.context) {
    const std::string data = fresh("ctxt_" + c.name);
    declare_variable(data, c.leaves);
    const auto id = find_type_spelled(data_, c.asn1_type);
    const asn1::TypeAssignment* assignment = id ? data_.type(*id) : nullptr;
    context_[folded(c.name)] =
        Ref{data, c.leaves, assignment ? definition(data_, assignment->type) : nullptr};
    const bool scalar = c.leaves.size() == 1 && c.leaves[0].suffix.empty();
    const std::optional<std::string> value = scalar ? context_value(c.leaves[0], c.value) : "";
    if (scalar && value) {
      initial_statements_.push_back(data + " = " + *value + ";");
    } else if (!c.value.empty()) {
      error(c.at, "the value '" + c.value + "' of context parameter " + c.name +
                      " is not translated (scalar values are)");
    }
  }
}

std::optional<Ref> Translator::context_field(const sdl::Expr& e) {
  const sdl::Expr& record = e.operands[0];
  const std::string own = function_.source ? function_.source->name : function_.name;
  if (record.kind != sdl::Expr::Kind::Name || folded(record.text) != folded(own) + "_ctxt") {
    return std::nullopt;
  }
  auto it = context_.find(folded(e.text));
  if (it == context_.end()) {
    error(e.at, "'" + e.text + "' is not a context parameter of " + own);
    return std::nullopt;
  }
  return it->second;
}

}  // namespace smcbip::taste2bip::detail
