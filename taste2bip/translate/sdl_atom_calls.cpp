// Outputs and calls: required interfaces (their data set, then `r_out`, and `r_result` for a
// synchronous one), timers, writeln/write as printf, and procedures inlined at the call.
#include <algorithm>

#include "bipc/utf8.h"
#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

const SignalInterface* find_interface(const std::vector<SignalInterface>& list,
                                      const std::string& name) {
  for (const SignalInterface& i : list) {
    if (folded(i.name) == folded(bip_identifier(name))) return &i;
  }
  return nullptr;
}

/// `text` inside a BIP string literal that printf reads as itself.
std::string format_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '%')
      out += "%%";
    else if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '\n')
      out += "\\n";
    else
      out += c;
  }
  return out;
}

}  // namespace

bool Translator::output(const sdl::OutputSignal& s, Step& step, Chain& chain) {
  const SignalInterface* r = find_interface(function_.required, s.name);
  if (r == nullptr) {
    error(s.at, "output '" + s.name + "' names no required interface of " + function_.name);
    return false;
  }
  return interface_call(*r, s.arguments, s.at, step, chain);
}

bool Translator::interface_call(const SignalInterface& r, const std::vector<sdl::Expr>& args,
                                const bipc::Location& at, Step& step, Chain& chain) {
  if (args.size() != r.parameters.size()) {
    error(at, "'" + r.name + "' takes " + std::to_string(r.parameters.size()) +
                  " parameters, given " + std::to_string(args.size()));
    return false;
  }
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!r.parameters[k].out &&
        !assign(interface_ref(r, r.parameters[k]), args[k], step.statements)) {
      return false;
    }
  }
  std::string next = place(chain);
  close(std::move(step), next);
  step = Step{false, r.name + "_out", next, "", {}};
  if (!r.synchronous()) {
    const bool outs = std::any_of(r.parameters.begin(), r.parameters.end(),
                                  [](const SignalParameter& p) { return p.out; });
    if (outs) {
      notes_.push_back("'" + r.name + "' reaches no synchronous interface: the call does not " +
                       "wait, its out parameters keep their values");
    }
    return true;
  }
  next = place(chain);
  close(std::move(step), next);
  step = Step{false, r.name + "_result", next, "", {}};
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!r.parameters[k].out) continue;
    std::optional<Ref> target = reference(args[k]);
    if (!target ||
        !assign_ref(*target, interface_ref(r, r.parameters[k]), args[k].at, step.statements)) {
      return false;
    }
  }
  return true;
}

bool Translator::call(const sdl::Action& a, Step& step, Chain& chain, Outcome& out, bool& ended) {
  const std::string f = folded(a.name);
  if (f == "set_timer" || f == "reset_timer") return timer_call(a, f == "set_timer", step);
  if ((f == "set" && a.arguments.size() == 2) || (f == "reset" && a.arguments.size() == 1)) {
    return sdl_timer_call(a, step);
  }
  if (f == "writeln" || f == "write") return write_call(a, f == "writeln", step);
  if (const SignalInterface* r = find_interface(function_.required, a.name)) {
    return interface_call(*r, a.arguments, a.at, step, chain);
  }
  if (const sdl::Procedure* p = choose_procedure(a.name, a.arguments.size())) {
    return procedure_call(*p, a, step, chain, out, ended);
  }
  error(a.at, "call of '" + a.name +
                  "' is not translated (no procedure with a body nor required interface of that "
                  "name)");
  return false;
}

const sdl::Procedure* Translator::choose_procedure(const std::string& name, std::size_t arguments) {
  const sdl::Procedure* chosen = nullptr;
  if (auto p = procedures_.find(folded(name)); p != procedures_.end()) {
    for (const sdl::Procedure* candidate : p->second) {
      if (!candidate->is_external && !candidate->is_referenced &&
          candidate->parameters.size() == arguments) {
        chosen = candidate;
      }
    }
  }
  return chosen;
}

bool Translator::call_for_value(const sdl::Expr& target, const sdl::Expr& call, Step& step,
                                Chain& chain, Outcome& out, bool& ended) {
  const sdl::Expr& callee = call.operands[0];
  const sdl::Procedure* p = callee.kind == sdl::Expr::Kind::Name
                                ? choose_procedure(callee.text, call.operands.size() - 1)
                                : nullptr;
  if (p == nullptr || procedure_results_.count(p) == 0) {
    error(call.at, "this call names no procedure with a body that returns a value");
    return false;
  }
  sdl::Action a;
  a.kind = sdl::Action::Kind::Call;
  a.name = callee.text;
  a.arguments.assign(call.operands.begin() + 1, call.operands.end());
  a.at = call.at;
  if (!procedure_call(*p, a, step, chain, out, ended) || ended) return false;
  std::optional<Ref> t = reference(target);
  return t && assign_ref(*t, procedure_results_.at(p), call.at, step.statements);
}

bool Translator::timer_call(const sdl::Action& a, bool set, Step& step) {
  const std::size_t expected = set ? 2 : 1;
  const sdl::Expr* timer = a.arguments.size() == expected ? &a.arguments.back() : nullptr;
  auto it = timer && timer->kind == sdl::Expr::Kind::Name ? timers_.find(signal_key(timer->text))
                                                          : timers_.end();
  if (it == timers_.end()) {
    error(a.at, std::string(set ? "set_timer(duration, timer)" : "reset_timer(timer)") +
                    " names no timer of the process");
    return false;
  }
  const std::string& t = it->second;
  if (!set) {
    step.statements.push_back(t + "_armed = false;");
    return true;
  }
  std::optional<Scalar> ms = scalar(a.arguments[0]);
  if (!ms) return false;
  step.statements.push_back(t + "_value = " + ms->text + ";");
  step.statements.push_back(t + "_clock = 0;");
  step.statements.push_back(t + "_armed = true;");
  return true;
}

bool Translator::sdl_timer_call(const sdl::Action& a, Step& step) {
  if (a.arguments.size() == 1) return timer_call(a, false, step);
  // SDL's `set(now + d, t)`: the timer expires d after now.
  const sdl::Expr& when = a.arguments[0];
  const bool relative = when.kind == sdl::Expr::Kind::Binary && when.op == sdl::Operator::Plus &&
                        when.operands[0].kind == sdl::Expr::Kind::Name &&
                        folded(when.operands[0].text) == "now";
  if (!relative) {
    error(when.at, "set with a time other than 'now + duration' is not translated");
    return false;
  }
  sdl::Action set = a;
  set.arguments[0] = when.operands[1];
  return timer_call(set, true, step);
}

bool Translator::write_call(const sdl::Action& a, bool newline, Step& step) {
  std::string format, values, types = "string";
  auto flush = [&]() {
    if (format.empty()) return;
    need_function("printf(" + types + ")");
    step.statements.push_back("printf(\"" + format + "\"" + values + ");");
    format.clear();
    values.clear();
    types = "string";
  };
  for (const sdl::Expr& e : a.arguments) {
    if (e.kind == sdl::Expr::Kind::String) {
      if (!bipc::is_utf8(e.text)) {
        error(e.at, "a string holding bytes that are not UTF-8 (BIP text is UTF-8)");
        return false;
      }
      format += format_text(e.text);
      continue;
    }
    std::optional<Scalar> v = scalar(e);
    if (!v) return false;
    if (v->kind == "bool") {
      // Printed as OpenGEODE does, without passing a bool to printf.
      flush();
      need_function("printf(string)");
      step.statements.push_back("if (" + v->text +
                                ") then printf(\"TRUE\"); else printf(\"FALSE\"); fi");
      continue;
    }
    format += v->kind == "float" ? "%g" : (v->kind == "string" ? "%s" : "%d");
    values += ", " + v->text;
    types += ", " + (v->kind.empty() ? std::string("int") : v->kind);
  }
  if (newline) format += "\\n";
  flush();
  return true;
}

bool Translator::procedure_call(const sdl::Procedure& p, const sdl::Action& a, Step& step,
                                Chain& chain, Outcome& out, bool& ended) {
  for (const sdl::Procedure* q : inlining_) {
    if (q == &p) {
      error(a.at, "recursive call of procedure '" + p.name + "' is not translated");
      return false;
    }
  }
  const std::vector<Ref>& params = procedure_parameters_[&p];
  if (a.arguments.size() != p.parameters.size() || params.size() != p.parameters.size()) {
    error(a.at, "procedure '" + p.name + "' takes " + std::to_string(p.parameters.size()) +
                    " parameters, given " + std::to_string(a.arguments.size()));
    return false;
  }
  for (std::size_t k = 0; k < params.size(); ++k) {
    const bool out_only = p.parameters[k].direction == sdl::FormalParameter::Direction::Out;
    if (!out_only && !assign(params[k], a.arguments[k], step.statements)) return false;
  }
  scopes_.push_back(procedure_scopes_[&p]);
  for (const sdl::Variable& v : p.body.variables) {
    if (v.initial && scopes_.back().count(folded(v.name)) > 0) {
      assign(*scopes_.back()[folded(v.name)].ref, *v.initial, step.statements);
    }
  }
  label_tables_.emplace_back();
  for (const sdl::FloatingLabel& l : p.body.labels) {
    label_tables_.back()[folded(l.name)] = LabelSite{&l.transition.actions, 0, true};
    collect_labels(l.transition.actions, true, label_tables_.back());
  }
  if (!p.body.starts.empty())
    collect_labels(p.body.starts[0].transition.actions, true, label_tables_.back());
  inlining_.push_back(&p);
  const std::string key = chain.key;
  chain.key += "/" + std::to_string(++inline_count_);
  Outcome o;
  if (p.body.starts.empty()) {
    o.falls.push_back(std::move(step));
  } else {
    o = actions(p.body.starts[0].transition.actions, 0, std::move(step), chain);
  }
  chain.key = key;
  inlining_.pop_back();
  label_tables_.pop_back();
  scopes_.pop_back();
  for (Step& r : o.returns) o.falls.push_back(std::move(r));
  std::optional<Step> next = join_falls(std::move(o.falls), chain);
  if (!next) {
    ended = true;
    return true;
  }
  step = std::move(*next);
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (p.parameters[k].direction == sdl::FormalParameter::Direction::In) continue;
    std::optional<Ref> target = reference(a.arguments[k]);
    if (!target || !assign_ref(*target, params[k], a.arguments[k].at, step.statements)) {
      return false;
    }
  }
  (void)out;
  return true;
}

}  // namespace smcbip::taste2bip::detail
