// Decisions as guarded eager steps out of one place (one internal port per answer, so the
// answers never share a port), and labels as places reached by sequence or by join.
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

/// Whether BIP compares values of these kinds (unknown kinds are left to the front end).
bool comparable(const std::string& a, const std::string& b) {
  const auto numeric = [](const std::string& k) { return k == "int" || k == "float"; };
  return a.empty() || b.empty() || a == b || (numeric(a) && numeric(b));
}

}  // namespace

Outcome Translator::decision(const sdl::Action& a, Step step, Chain& chain) {
  const sdl::Decision& d = a.decision;
  const std::string at = place(chain);
  close(std::move(step), at);
  Outcome out;
  const bool any = d.is_any || d.question.kind == sdl::Expr::Kind::String;
  if (any && !d.is_any) {
    notes_.push_back("informal decision '" + d.question.text +
                     "': its answers are a non-deterministic choice");
  }
  std::vector<std::string> guards;
  for (std::size_t k = 0; k < d.answers.size(); ++k) {
    const sdl::Answer& answer = d.answers[k];
    std::string guard;
    if (!any && answer.is_else) {
      for (const std::string& g : guards) guard += (guard.empty() ? "" : " || ") + g;
      guard = guard.empty() ? "" : "!(" + guard + ")";
    } else if (!any) {
      std::optional<std::string> g = answer_guard(d.question, answer);
      if (!g) continue;
      guards.push_back(*g);
      guard = *g;
    }
    out.merge(actions(answer.transition.actions, 0, open(at, k, guard), chain));
  }
  return out;
}

std::optional<std::string> Translator::answer_guard(const sdl::Expr& question,
                                                    const sdl::Answer& answer) {
  const asn1::Type* hint = type_of(question);
  const bool structured =
      hint != nullptr &&
      (hint->kind == asn1::TypeKind::Sequence || hint->kind == asn1::TypeKind::SequenceOf ||
       (hint->kind == asn1::TypeKind::Choice && question.kind != sdl::Expr::Kind::Call));
  if (structured) return structured_answer(question, answer);
  std::optional<Scalar> q = scalar(question, hint);
  if (!q) return std::nullopt;
  std::string guard;
  for (const sdl::RangeCondition& c : answer.conditions) {
    std::optional<Scalar> low = scalar(c.low, hint);
    if (!low) return std::nullopt;
    if (!comparable(q->kind, low->kind)) {
      error(c.at, "an answer of type " + low->kind + " to a question of type " + q->kind);
      return std::nullopt;
    }
    std::string text;
    if (c.kind == sdl::RangeCondition::Kind::Closed) {
      std::optional<Scalar> high = scalar(c.high, hint);
      if (!high) return std::nullopt;
      text = "(" + q->text + " >= " + low->text + " && " + q->text + " <= " + high->text + ")";
    } else {
      const char* op = "==";
      switch (c.op) {
        case sdl::Operator::NotEqual:
          op = "!=";
          break;
        case sdl::Operator::Less:
          op = "<";
          break;
        case sdl::Operator::LessEqual:
          op = "<=";
          break;
        case sdl::Operator::Greater:
          op = ">";
          break;
        case sdl::Operator::GreaterEqual:
          op = ">=";
          break;
        default:
          break;
      }
      text = "(" + q->text + " " + op + " " + low->text + ")";
    }
    guard += (guard.empty() ? "" : " || ") + text;
  }
  if (guard.empty()) {
    error(answer.at, "an answer without a condition is not translated");
    return std::nullopt;
  }
  return "(" + guard + ")";
}

std::optional<std::string> Translator::structured_answer(const sdl::Expr& question,
                                                         const sdl::Answer& answer) {
  std::string guard;
  for (const sdl::RangeCondition& c : answer.conditions) {
    if (c.kind != sdl::RangeCondition::Kind::Value || c.op != sdl::Operator::Equal) {
      error(c.at, "a structured value is compared by equality only");
      return std::nullopt;
    }
    std::optional<Scalar> equal = equality(question, c.low, true, c.at);
    if (!equal) return std::nullopt;
    guard += (guard.empty() ? "" : " || ") + equal->text;
  }
  return "(" + guard + ")";
}

Outcome Translator::label(const std::string& name, const bipc::Location& at, Step step,
                          Chain& chain, bool sequential, const std::vector<sdl::Action>* list,
                          std::size_t index) {
  const std::string key = folded(name) + "@" + chain.key;
  if (auto it = label_places_.find(key); it != label_places_.end()) {
    close(std::move(step), it->second);
    return {};
  }
  LabelSite site{list, index, true};
  if (!sequential) {
    const LabelSite* found = nullptr;
    for (auto it = label_tables_.rbegin(); it != label_tables_.rend() && !found; ++it) {
      if (auto l = it->find(folded(name)); l != it->end()) found = &l->second;
    }
    if (found == nullptr) {
      error(at, "join to '" + name + "', which is not a label");
      return {};
    }
    site = *found;
  }
  const std::string target = place(chain);
  label_places_[key] = target;
  close(std::move(step), target);
  Outcome out = actions(*site.actions, site.index, open(target), chain);
  if (!sequential && !site.top_level && !out.falls.empty()) {
    error(at, "a join to label '" + name + "' inside a decision answer is not translated");
  }
  return out;
}

}  // namespace smcbip::taste2bip::detail
