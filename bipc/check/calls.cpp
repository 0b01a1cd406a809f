// Calls of extern functions and uses of extern operators: matching prototypes by arity and
// compatible argument types, then the strictly most precise one (language.rst, "Actions").
#include "bipc/check/detail/check_internal.h"

namespace smcbip::bipc::detail {

namespace {

using Kind = ast::ValueType::Kind;
using Where = ExprContext::Where;
using Prototypes = std::vector<const ast::ExternFunctionDecl*>;

const ast::ValueType& param_type(const ast::ExternFunctionDecl& f, std::size_t i) {
  return f.params[i].type.resolved;
}

bool accepts(const ast::ExternFunctionDecl& f, const std::vector<ast::ValueType>& args) {
  if (f.params.size() != args.size()) return false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!assignable(args[i], param_type(f, i))) return false;
  }
  return true;
}

bool same_params(const ast::ExternFunctionDecl& a, const ast::ExternFunctionDecl& b) {
  for (std::size_t i = 0; i < a.params.size(); ++i) {
    if (!(param_type(a, i) == param_type(b, i))) return false;
  }
  return true;
}

ast::ValueType result_of(const ast::ExternFunctionDecl& f) {
  return f.result ? f.result->resolved : ast::ValueType{Kind::Void, nullptr};
}

/// `a` is strictly more precise than `b`: every parameter compatible, at least one a subtype.
bool more_precise(const ast::ExternFunctionDecl& a, const ast::ExternFunctionDecl& b) {
  for (std::size_t i = 0; i < a.params.size(); ++i) {
    if (!assignable(param_type(a, i), param_type(b, i))) return false;
  }
  return !same_params(a, b);
}

/// Drops repeated declarations of one prototype (the same header seen through two packages);
/// equal parameters with different results stay, and make the call ambiguous.
Prototypes distinct(const Prototypes& matches) {
  Prototypes kept;
  for (const ast::ExternFunctionDecl* f : matches) {
    bool repeated = false;
    for (const ast::ExternFunctionDecl* g : kept) {
      repeated = repeated || (same_params(*f, *g) && result_of(*f) == result_of(*g));
    }
    if (!repeated) kept.push_back(f);
  }
  return kept;
}

struct Choice {
  const ast::ExternFunctionDecl* decl = nullptr;
  Prototypes matching;  // all distinct matching prototypes
};

Choice choose(const Prototypes& candidates, const std::vector<ast::ValueType>& args) {
  Choice choice;
  Prototypes matching;
  for (const ast::ExternFunctionDecl* f : candidates) {
    if (accepts(*f, args)) matching.push_back(f);
  }
  choice.matching = distinct(matching);
  for (const ast::ExternFunctionDecl* f : choice.matching) {
    bool best = true;
    for (const ast::ExternFunctionDecl* g : choice.matching) {
      best = best && (f == g || more_precise(*f, *g));
    }
    if (best) choice.decl = f;
  }
  return choice;
}

std::string prototype_text(const ast::ExternFunctionDecl& f) {
  std::vector<ast::ValueType> params;
  for (std::size_t i = 0; i < f.params.size(); ++i) params.push_back(param_type(f, i));
  std::string text = f.result ? type_name(result_of(f)) + " " : std::string();
  return text + f.name.text + type_list(params);
}

void note_candidates(const Prototypes& candidates, Diagnostics& diags) {
  for (const ast::ExternFunctionDecl* f : candidates) {
    diags.note(f->name.loc, "candidate: " + prototype_text(*f));
  }
}

/// Guards and other constant contexts must not modify data: no call whose prototype takes a
/// parameter by non-const reference.
bool constant_context(Where where) {
  return where != Where::AtomInit && where != Where::AtomAction && where != Where::ConnectorUp &&
         where != Where::ConnectorDown;
}

void check_constness(ast::Expr& call, const ast::ExternFunctionDecl& f, const ExprContext& ctx,
                     Diagnostics& diags) {
  for (std::size_t i = 0; i < f.params.size() && i < call.operands.size(); ++i) {
    if (f.params[i].type.is_const || !call.operands[i]) continue;
    const ast::Expr& arg = *call.operands[i];
    if (constant_context(ctx.where)) {
      diags.error(arg.loc, "a guard cannot call '" + f.name.text + "' with a non-const parameter " +
                               std::to_string(i + 1) + ": it may modify its argument");
      return;
    }
    if (names_constant(arg, ctx)) {
      diags.error(arg.loc, "cannot pass constant '" + name_text(arg) + "' to non-const parameter " +
                               std::to_string(i + 1) + " of '" + f.name.text + "'");
    }
  }
}

Prototypes functions_named(const ast::Expr& call, const ExprContext& ctx, const Symbols& symbols) {
  Prototypes found;
  if (ctx.package == nullptr) return found;
  for (const ast::ExternFunctionDecl* f : symbols.functions(*ctx.package, call.name.text())) {
    if (!f->is_operator) found.push_back(f);
  }
  return found;
}

}  // namespace

ast::ValueType check_call(ast::Expr& call, const ExprContext& ctx, const Symbols& symbols,
                          Diagnostics& diags, bool allow_void) {
  std::vector<ast::ValueType> args;
  bool failed = false;
  for (ast::ExprPtr& arg : call.operands) {
    args.push_back(arg ? check_value(*arg, ctx, symbols, diags, false) : ast::ValueType{});
    failed = failed || args.back().kind == Kind::Error;
  }
  const std::string name = call.name.text();
  const Location at = call.name.parts.empty() ? call.loc : call.name.loc();
  const Prototypes candidates = functions_named(call, ctx, symbols);
  if (candidates.empty()) {
    diags.error(at, "undeclared function '" + name +
                        "': expected an extern function declared "
                        "in this package or a used one");
    return {};
  }
  if (failed) return {};
  if (ctx.where == Where::ConstInit) {
    diags.error(at, "a constant must be initialised with a constant expression, not a call of '" +
                        name + "'");
    return {};
  }
  const Choice choice = choose(candidates, args);
  if (choice.matching.empty()) {
    diags.error(at, "no matching prototype for call to '" + name + "' with argument types " +
                        type_list(args));
    note_candidates(candidates, diags);
    return {};
  }
  if (choice.decl == nullptr) {
    diags.error(at, "ambiguous call to '" + name + "' with argument types " + type_list(args) +
                        ": no prototype is more precise than the others");
    note_candidates(choice.matching, diags);
    return {};
  }
  call.function = choice.decl;
  check_constness(call, *choice.decl, ctx, diags);
  const ast::ValueType result = result_of(*choice.decl);
  if (result.kind == Kind::Void && !allow_void) {
    diags.error(at, "function '" + name +
                        "' has no return value: it can only be called as a "
                        "statement");
    return {};
  }
  return result;
}

OperatorMatch match_operator(const std::string& symbol, const std::vector<ast::ValueType>& operands,
                             const ExprContext& ctx, const Symbols& symbols) {
  OperatorMatch match;
  if (ctx.package == nullptr) return match;
  Prototypes candidates;
  for (const ast::ExternFunctionDecl* f : symbols.functions(*ctx.package, symbol)) {
    if (f->is_operator && f->params.size() == operands.size()) candidates.push_back(f);
  }
  match.exists = !candidates.empty();
  const Choice choice = choose(candidates, operands);
  match.decl = choice.decl;
  match.ambiguous = choice.decl == nullptr && !choice.matching.empty();
  return match;
}

}  // namespace smcbip::bipc::detail
