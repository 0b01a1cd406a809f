// SDL `for` loops: over a range of constants or the elements of a SEQUENCE OF of fixed size,
// unrolled (at most 64 iterations); over a range with bounds known only at run time, a loop of
// places with the loop variable as data.
#include <algorithm>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

/// The largest number of iterations of a `for` loop unrolled.
constexpr std::size_t kMaxIterations = 64;

bool is_range(const sdl::Expr& it) {
  return it.kind == sdl::Expr::Kind::Call && it.operands.size() >= 2 && it.operands.size() <= 4 &&
         it.operands[0].kind == sdl::Expr::Kind::Name && folded(it.operands[0].text) == "range";
}

}  // namespace

bool Translator::for_loop(const sdl::ForLoop& loop, Step& step, Chain& chain, Outcome& out,
                          bool& ended) {
  const sdl::Expr& it = loop.iterable;
  std::vector<Binding> values;
  if (!is_range(it)) {
    std::optional<Ref> seq = reference(it);
    if (!seq) return false;
    if (seq->type == nullptr || seq->type->kind != asn1::TypeKind::SequenceOf) {
      error(it.at, "a loop over a value that is not a SEQUENCE OF spread over data");
      return false;
    }
    for (const Leaf& l : seq->leaves) {
      if (l.asn1_type == nullptr && l.suffix == "length") {
        return elements_in_net(loop, *seq, l, step, chain, out);
      }
    }
    return element_values(*seq, it, values) && unrolled(loop, values, step, chain, out, ended);
  }
  std::vector<std::int64_t> bounds;
  for (std::size_t k = 1; k < it.operands.size(); ++k) {
    std::optional<std::int64_t> c = constant(it.operands[k]);
    if (!c) return loop_in_net(loop, step, chain, out);
    bounds.push_back(*c);
  }
  const std::int64_t low = bounds.size() >= 2 ? bounds[0] : 0;
  const std::int64_t high = bounds.size() >= 2 ? bounds[1] : bounds[0];
  const std::int64_t by = bounds.size() >= 3 ? bounds[2] : 1;
  if (by == 0) {
    error(it.at, "a range with a step of 0");
    return false;
  }
  for (std::int64_t v = low; by > 0 ? v < high : v > high;) {
    if (values.size() == kMaxIterations) {
      error(it.at, "a loop of more than 64 iterations is not unrolled");
      return false;
    }
    values.push_back(Binding{std::nullopt, v});
    if (__builtin_add_overflow(v, by, &v)) break;  // the next value is beyond any bound
  }
  return unrolled(loop, values, step, chain, out, ended);
}

bool Translator::element_values(const Ref& seq_ref, const sdl::Expr& sequence,
                                std::vector<Binding>& values) {
  const Ref* seq = &seq_ref;
  for (std::int64_t k = 0;; ++k) {
    bool found = false;
    for (const Leaf& l : seq->leaves) {
      found = found || (!l.path.empty() && l.path[0] == std::to_string(k));
    }
    if (!found) return true;
    std::optional<Ref> e = element(*seq, k, sequence.at);
    if (!e) return false;
    values.push_back(Binding{*e, 0});
  }
}

bool Translator::unrolled(const sdl::ForLoop& loop, const std::vector<Binding>& values, Step& step,
                          Chain& chain, Outcome& out, bool& ended) {
  const std::string outer_key = chain.key;
  for (std::size_t i = 0; i < values.size(); ++i) {
    // Each iteration's labels are places of its own: a label met again in the next iteration
    // must not lead back into this one.
    chain.key = outer_key + "/for" + std::to_string(loop.at.line) + ":" +
                std::to_string(loop.at.column) + "#" + std::to_string(i);
    scopes_.push_back({{folded(loop.variable), values[i]}});
    Outcome o = actions(loop.body.actions, 0, std::move(step), chain);
    scopes_.pop_back();
    chain.key = outer_key;
    for (Step& r : o.returns) out.returns.push_back(std::move(r));
    std::optional<Step> next = join_falls(std::move(o.falls), chain);
    if (!next) {
      ended = true;
      return true;
    }
    step = std::move(*next);
  }
  return true;
}

bool Translator::loop_in_net(const sdl::ForLoop& loop, Step& step, Chain& chain, Outcome& out) {
  const std::vector<sdl::Expr>& args = loop.iterable.operands;
  std::optional<Scalar> low = args.size() >= 3 ? scalar(args[1]) : Scalar{"0", "int"};
  std::optional<Scalar> high = scalar(args.size() >= 3 ? args[2] : args[1]);
  std::optional<std::int64_t> by = args.size() == 4 ? constant(args[3]) : 1;
  if (!low || !high) return false;
  if (!by || *by == 0) {
    error(loop.iterable.at, "a range whose step is not a constant other than 0");
    return false;
  }
  const std::string var = fresh(bip_identifier(loop.variable) + "_for");
  const Binding binding{Ref{var, {Leaf{"", "int", nullptr, {}}}, nullptr}, 0};
  return net_loop(loop, var, low->text, high->text, *by, {}, binding, step, chain, out);
}

bool Translator::elements_in_net(const sdl::ForLoop& loop, const Ref& seq, const Leaf& length,
                                 Step& step, Chain& chain, Outcome& out) {
  std::optional<Ref> first = element(seq, 0, loop.iterable.at);
  if (!first) return false;
  const std::string var = fresh(bip_identifier(loop.variable) + "_for");
  Ref current = *first;
  current.data = fresh(bip_identifier(loop.variable) + "_element");
  declare_variable(current.data, current.leaves);
  // Each iteration copies the element at the index into the loop variable's data.
  std::vector<std::string> prelude;
  for (std::int64_t k = 0;; ++k) {
    const bool exists = std::any_of(seq.leaves.begin(), seq.leaves.end(), [&](const Leaf& l) {
      return !l.path.empty() && l.path[0] == std::to_string(k);
    });
    if (!exists) break;
    std::vector<std::string> copy;
    std::optional<Ref> e = element(seq, k, loop.iterable.at);
    if (!e || !assign_ref(current, *e, loop.iterable.at, copy)) return false;
    std::string text = "if (" + var + " == " + std::to_string(k) + ") then";
    for (const std::string& c : copy) text += " " + c;
    prelude.push_back(text + " fi");
  }
  return net_loop(loop, var, "0", leaf_name(seq.data, length), 1, prelude, Binding{current, 0},
                  step, chain, out);
}

bool Translator::net_loop(const sdl::ForLoop& loop, const std::string& var, const std::string& low,
                          const std::string& high, std::int64_t by,
                          std::vector<std::string> prelude, const Binding& binding, Step& step,
                          Chain& chain, Outcome& out) {
  const std::string end = fresh(var + "_end");
  data_text_ += "    data int " + var + " = 0\n    data int " + end + " = 0\n";
  step.statements.push_back(var + " = " + low + ";");
  step.statements.push_back(end + " = " + high + ";");
  const std::string head = place(chain);
  close(std::move(step), head);
  const std::string more = var + (by > 0 ? " < " : " > ") + end;
  Step body = open(head, 0, more);
  body.statements = std::move(prelude);
  scopes_.push_back({{folded(loop.variable), binding}});
  Outcome o = actions(loop.body.actions, 0, std::move(body), chain);
  scopes_.pop_back();
  for (Step& r : o.returns) out.returns.push_back(std::move(r));
  if (std::optional<Step> next = join_falls(std::move(o.falls), chain)) {
    next->statements.push_back(var + " = " + var + " + " + std::to_string(by) + ";");
    close(std::move(*next), head);
  }
  step = open(head, 1, "!(" + more + ")");
  return true;
}

}  // namespace smcbip::taste2bip::detail
