// Small lookup helpers of the checker: one namespace of declarations, identifier lists, names.
#include <algorithm>
#include <tuple>

#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

bool NameScope::declare(const ast::Ident& name) {
  if (name.text.empty()) return true;
  auto [found, inserted] = first_.emplace(name.text, name.loc);
  if (inserted) return true;
  diags_.error(name.loc, "duplicate declaration of '" + name.text + "'");
  diags_.note(found->second, "'" + name.text + "' is first declared here");
  return false;
}

void declare_in_source_order(std::vector<const ast::Ident*> names, Diagnostics& diags) {
  std::stable_sort(names.begin(), names.end(), [](const ast::Ident* a, const ast::Ident* b) {
    return std::tie(a->loc.file, a->loc.line, a->loc.column) <
           std::tie(b->loc.file, b->loc.line, b->loc.column);
  });
  NameScope scope(diags);
  for (const ast::Ident* name : names) scope.declare(*name);
}

int index_of_ident(const std::vector<ast::Ident>& idents, const std::string& name) {
  for (std::size_t i = 0; i < idents.size(); ++i) {
    if (idents[i].text == name) return static_cast<int>(i);
  }
  return -1;
}

std::string name_text(const ast::Expr& expr) { return expr.name.text(); }

bool clocks_comparable(ExprContext::Where where) {
  return where == ExprContext::Where::AtomGuard || where == ExprContext::Where::Invariant ||
         where == ExprContext::Where::Resume;
}

}  // namespace smcbip::bipc::detail
