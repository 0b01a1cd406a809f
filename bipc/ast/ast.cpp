// Small helpers of the syntax tree.
#include "bipc/ast/ast.h"

namespace smcbip::bipc::ast {

std::string QualifiedName::text() const {
  std::string joined;
  for (const Ident& part : parts) {
    if (!joined.empty()) joined += '.';
    joined += part.text;
  }
  return joined;
}

}  // namespace smcbip::bipc::ast
