// The actions of an SDL transition as steps: tasks and loops add statements to the open step;
// outputs, calls and decisions close it; terminators end the chain in a state.
#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

Outcome Translator::actions(const std::vector<sdl::Action>& list, std::size_t from, Step step,
                            Chain& chain) {
  Outcome out;
  for (std::size_t i = from; i < list.size(); ++i) {
    const sdl::Action& a = list[i];
    if (a.kind == sdl::Action::Kind::Label) {
      out.merge(label(a.name, a.at, std::move(step), chain, true, &list, i + 1));
      return out;
    }
    if (a.kind == sdl::Action::Kind::Decision) {
      Outcome d = decision(a, std::move(step), chain);
      for (Step& r : d.returns) out.returns.push_back(std::move(r));
      std::optional<Step> next = join_falls(std::move(d.falls), chain);
      if (!next) return out;
      step = std::move(*next);
      continue;
    }
    bool ended = false;
    if (!action(a, step, chain, out, ended) || ended) return out;
  }
  out.falls.push_back(std::move(step));
  return out;
}

std::optional<Step> Translator::join_falls(std::vector<Step> falls, Chain& chain) {
  if (falls.empty()) return std::nullopt;
  if (falls.size() == 1) return std::move(falls[0]);
  const std::string joined = place(chain);
  for (Step& s : falls) close(std::move(s), joined);
  return open(joined);
}

bool Translator::action(const sdl::Action& a, Step& step, Chain& chain, Outcome& out, bool& ended) {
  using K = sdl::Action::Kind;
  switch (a.kind) {
    case K::Task:
      for (const sdl::TaskElement& t : a.task) {
        if (!task(t, step, chain, out, ended) || ended) return false;
      }
      return true;
    case K::Output:
      for (const sdl::OutputSignal& s : a.outputs) {
        if (!output(s, step, chain)) return false;
      }
      return true;
    case K::Call:
      return call(a, step, chain, out, ended);
    case K::Join:
      ended = true;
      out.merge(label(a.name, a.at, std::move(step), chain, false, nullptr, 0));
      return true;
    case K::NextState:
    case K::Stop:
      ended = true;
      return next_state(a, std::move(step), chain);
    case K::Return:
      ended = true;
      return return_action(a, step, chain, out);
    default:
      error(a.at, "this action is not translated");
      return false;
  }
}

bool Translator::next_state(const sdl::Action& a, Step step, Chain& chain) {
  if (a.kind == sdl::Action::Kind::Stop) {
    if (stop_place_.empty()) {
      stop_place_ = fresh("STOPPED");
      places_.push_back(stop_place_);
      notes_.push_back("'stop' leads to the place " + stop_place_ + ", which has no way out");
    }
    terminate(std::move(step), stop_place_, chain);
    return true;
  }
  if (a.name == "-" && chain.origin.empty()) {
    error(a.at, "'nextstate -' in the start transition has no state to go back to");
    return false;
  }
  std::optional<std::string> target = a.name == "-"
                                          ? std::optional<std::string>(chain.origin)
                                          : state_place(a.name, a.via, chain.origin, a.at);
  if (target) terminate(std::move(step), *target, chain);
  return target.has_value();
}

bool Translator::return_action(const sdl::Action& a, Step& step, Chain& chain, Outcome& out) {
  if (inlining_.empty() && level_ != nullptr && level_->composite != nullptr) {
    return exit_composite(a, step, chain, out);
  }
  if (inlining_.empty()) {
    error(a.at, "return outside a procedure or a nested state");
    return false;
  }
  if (a.value) {
    auto result = procedure_results_.find(inlining_.back());
    if (result == procedure_results_.end()) {
      error(a.value->at, "a value returned by a procedure that declares no result type");
      return false;
    }
    if (!assign(result->second, *a.value, step.statements)) return false;
  }
  out.returns.push_back(std::move(step));
  return true;
}

bool Translator::task(const sdl::TaskElement& t, Step& step, Chain& chain, Outcome& out,
                      bool& ended) {
  switch (t.kind) {
    case sdl::TaskElement::Kind::Assignment:
      if (t.value.kind == sdl::Expr::Kind::ProcedureCall) {
        return call_for_value(t.target, t.value, step, chain, out, ended);
      }
      return assign_statement(t.target, t.value, step.statements);
    case sdl::TaskElement::Kind::Informal:
      notes_.push_back("informal task '" + t.text + "' is not executed");
      return true;
    case sdl::TaskElement::Kind::ForLoop:
      return for_loop(t.loop.at(0), step, chain, out, ended);
  }
  return false;
}

void Translator::terminate(Step step, const std::string& target, Chain& chain) {
  if (chain.serving != nullptr) {
    for (const auto& [interface_data, variable] : chain.out_copies) {
      assign_ref(interface_data, variable, chain.serving->at, step.statements);
    }
    const std::string before = place(chain);
    close(std::move(step), before);
    step = Step{false, chain.serving->name + "_return", before, "", {}};
  }
  if (!chain.busy.empty()) step.statements.push_back(chain.busy + " = false;");
  close(std::move(step), target);
}

std::optional<std::string> Translator::state_place(const std::string& name, const std::string& via,
                                                   const std::string& origin,
                                                   const bipc::Location& at) {
  if (auto it = level_->composites.find(folded(name)); it != level_->composites.end()) {
    return entry_place(*it->second, via, origin);
  }
  auto it = level_->states.find(folded(name));
  if (it != level_->states.end() && via.empty()) return it->second;
  error(at, "'" + name + "' is not a " + (via.empty() ? "state" : "nested state") + " here");
  return std::nullopt;
}

}  // namespace smcbip::taste2bip::detail
