// What a stable state does with each provided interface's call, each timer's expiry and its
// continuous signals. Explicit `state S` blocks take precedence over `state *` ones.
#include <algorithm>
#include <limits>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

namespace {

struct Handler {
  const sdl::Input* input = nullptr;
  const sdl::InputSignal* signal = nullptr;
};

}  // namespace

void Translator::translate_state(const std::string& state) {
  const std::string& at = states_.at(state);
  std::vector<const sdl::State*> blocks;
  for (bool any : {false, true}) {
    for (const sdl::State& s : process_.body.states) {
      if (s.is_any == any && state_applies(s, state)) blocks.push_back(&s);
    }
  }
  std::map<std::string, Handler> handled;  // folded signal name
  const sdl::Input* any_input = nullptr;
  bool save_all = false;
  std::vector<std::string> saved;
  for (const sdl::State* s : blocks) {
    for (const sdl::Input& input : s->inputs) {
      if (input.is_any && any_input == nullptr) any_input = &input;
      for (const sdl::InputSignal& sig : input.signals) {
        if (handled.count(folded(sig.name)) == 0) handled[folded(sig.name)] = {&input, &sig};
      }
    }
    for (const std::string& n : s->saves) {
      save_all = save_all || n == "*";
      saved.push_back(folded(n));
    }
  }
  for (const auto& [name, h] : handled) {
    const bool known =
        timers_.count(name) > 0 ||
        std::any_of(function_.provided.begin(), function_.provided.end(),
                    [&](const SignalInterface& p) { return folded(p.name) == name; });
    if (!known)
      error(h.signal->at, "input '" + h.signal->name +
                              "' names no provided interface "
                              "or timer of " +
                              function_.name);
  }
  for (const SignalInterface& p : function_.provided) {
    auto h = handled.find(folded(p.name));
    if (h != handled.end()) {
      input_transition(at, p, h->second.input, h->second.signal);
    } else if (any_input != nullptr) {
      input_transition(at, p, any_input, nullptr);
    } else if (save_all || std::count(saved.begin(), saved.end(), folded(p.name)) > 0) {
      notes_.push_back("'" + p.name + "' is saved in state " + at + ": the call waits there");
    } else {
      input_transition(at, p, nullptr, nullptr);
    }
  }
  for (const auto& [name, base] : timers_) {
    auto h = handled.find(name);
    timer_transition(at, base, h != handled.end() ? h->second.input : any_input);
  }
  continuous_transitions(state, at);
}

void Translator::input_transition(const std::string& state, const SignalInterface& p,
                                  const sdl::Input* input, const sdl::InputSignal* signal) {
  Chain chain{state, state + "/" + p.name, &p, {}};
  Step step{false, p.name + "_in", state, "", {}};
  if (signal != nullptr) {
    if (signal->parameters.size() > p.parameters.size()) {
      error(signal->at, "'" + p.name + "' has " + std::to_string(p.parameters.size()) +
                            " parameters, the input names " +
                            std::to_string(signal->parameters.size()));
      return;
    }
    for (std::size_t k = 0; k < signal->parameters.size(); ++k) {
      sdl::Expr name{
          sdl::Expr::Kind::Name, sdl::Operator::None, signal->parameters[k], {}, {}, signal->at};
      std::optional<Ref> variable = reference(name);
      if (!variable) return;
      const Ref data = interface_ref(p, p.parameters[k]);
      if (p.parameters[k].out) {
        chain.out_copies.emplace_back(data, *variable);
      } else if (!assign_ref(*variable, data, signal->at, step.statements)) {
        return;
      }
    }
  }
  if (input == nullptr) {
    terminate(std::move(step), state, chain);
    return;
  }
  if (input->enabling) {
    std::optional<Scalar> guard = scalar(*input->enabling);
    if (!guard) return;
    step.guard = guard->text;
    notes_.push_back("'" + p.name + "' waits in state " + state +
                     " while its enabling "
                     "condition is false");
  }
  chain_end(actions(input->transition.actions, 0, std::move(step), chain), input->at);
}

void Translator::timer_transition(const std::string& state, const std::string& timer,
                                  const sdl::Input* input) {
  Chain chain{state, state + "/" + timer, nullptr, {}};
  Step step{false,
            timer + "_expired",
            state,
            timer + "_armed && " + timer + "_clock >= " + timer + "_value",
            {timer + "_armed = false;"}};
  if (input == nullptr) {
    close(std::move(step), state);
    return;
  }
  chain_end(actions(input->transition.actions, 0, std::move(step), chain), input->at);
}

void Translator::continuous_transitions(const std::string& state, const std::string& place) {
  std::vector<std::pair<std::int64_t, const sdl::ContinuousSignal*>> signals;
  for (const sdl::State& s : process_.body.states) {
    if (!state_applies(s, state)) continue;
    for (const sdl::ContinuousSignal& c : s.continuous) {
      std::int64_t priority = std::numeric_limits<std::int64_t>::max();
      if (c.priority) {
        std::optional<std::int64_t> n = constant(*c.priority);
        if (!n) error(c.priority->at, "a priority that is not a constant is not translated");
        priority = n.value_or(priority);
      }
      signals.emplace_back(priority, &c);
    }
  }
  std::stable_sort(signals.begin(), signals.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string higher;
  for (std::size_t k = 0; k < signals.size(); ++k) {
    const sdl::ContinuousSignal& c = *signals[k].second;
    std::optional<Scalar> condition = scalar(c.condition);
    if (!condition) continue;
    const std::string guard =
        higher.empty() ? condition->text : condition->text + " && !(" + higher + ")";
    higher += (higher.empty() ? "" : " || ") + condition->text;
    Chain chain{place, place + "/continuous" + std::to_string(k), nullptr, {}};
    chain_end(actions(c.transition.actions, 0, open(place, k, guard), chain), c.at);
  }
  if (!signals.empty()) {
    notes_.push_back("the continuous signals of state " + place +
                     " fire as soon as they hold (eager), before waiting calls");
  }
}

}  // namespace smcbip::taste2bip::detail
