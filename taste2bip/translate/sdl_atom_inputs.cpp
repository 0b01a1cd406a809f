// What a stable state does with each provided interface's call, each timer's expiry and its
// continuous signals. Explicit `state S` blocks take precedence over `state *` ones.
#include <algorithm>
#include <limits>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

void Translator::refuse_unknown_inputs(const std::map<std::string, Handler>& handled) {
  for (const auto& [key, h] : handled) {
    const std::string& name = key;  // clang 14 cannot capture a structured binding
    const bool known =
        timers_.count(name) > 0 ||
        std::any_of(function_.provided.begin(), function_.provided.end(),
                    [&](const SignalInterface& p) { return signal_key(p.name) == name; });
    if (!known && reported_.insert(h.signal).second) {
      error(h.signal->at,
            name == "none_" || name == "none"
                ? std::string("a spontaneous transition (input none) is not translated")
                : "input '" + h.signal->name + "' names no provided interface or timer of " +
                      function_.name);
    }
  }
}

void Translator::translate_state(const StableState& state) {
  const std::string& at = state.place;
  const auto blocks = blocks_of(state);
  std::map<std::string, Handler> handled;  // folded signal name
  Handler any_input;
  bool save_all = false;
  std::vector<std::string> saved;
  for (const auto& [s, level] : blocks) {
    for (const sdl::Input& input : s->inputs) {
      if (input.is_any && any_input.input == nullptr) any_input = Handler{&input, nullptr, level};
      for (const sdl::InputSignal& sig : input.signals) {
        if (handled.count(signal_key(sig.name)) == 0) {
          handled[signal_key(sig.name)] = Handler{&input, &sig, level};
        }
      }
    }
    for (const std::string& n : s->saves) {
      save_all = save_all || n == "*";
      saved.push_back(signal_key(n));
    }
  }
  refuse_unknown_inputs(handled);
  const auto region_and_aggregation = region_of(state);  // clang 14 cannot capture bindings
  const sdl::CompositeState* region = region_and_aggregation.first;
  const Level* aggregation = region_and_aggregation.second;
  auto owned = [&](const std::string& key) {
    return region == nullptr || owner_region(*aggregation, key) == region;
  };
  if (region != nullptr) refuse_outer_transitions(state, *aggregation, blocks);
  aggregation_ = aggregation;
  for (const SignalInterface& p : function_.provided) {
    if (!owned(signal_key(p.name))) continue;
    auto h = handled.find(signal_key(p.name));
    if (faults_only_) {
      if (is_fault_interface(p) && h != handled.end()) fault_transition(at, p, h->second);
      continue;
    }
    if (h != handled.end()) {
      input_transition(at, p, h->second);
    } else if (any_input.input != nullptr) {
      input_transition(at, p, any_input);
    } else if (save_all || std::count(saved.begin(), saved.end(), signal_key(p.name)) > 0) {
      notes_.push_back("'" + p.name + "' is saved in state " + at + ": the call waits there");
    } else {
      input_transition(at, p, Handler{nullptr, nullptr, state.level});
    }
  }
  if (faults_only_) return;  // timers and continuous signals are nominal behaviour
  for (const auto& [name, base] : timers_) {
    if (!owned(name)) continue;
    auto h = handled.find(name);
    timer_transition(at, base, h != handled.end() ? h->second : any_input);
  }
  continuous_transitions(state, blocks);
}

void Translator::refuse_outer_transitions(
    const StableState& state, const Level& aggregation,
    const std::vector<std::pair<const sdl::State*, const Level*>>& blocks) {
  std::vector<const Level*> inside;
  for (const Level* l = state.level; l != &aggregation; l = l->parent) inside.push_back(l);
  for (const auto& [s, level] : blocks) {
    const bool outer = std::find(inside.begin(), inside.end(), level) == inside.end();
    const bool acts = !s->inputs.empty() || !s->continuous.empty() || !s->connections.empty();
    if (outer && acts && refused_blocks_.insert(s).second) {
      error(s->at, "transitions of a state enclosing a state aggregation are not translated");
    }
  }
}

std::pair<const sdl::CompositeState*, const Level*> Translator::region_of(
    const StableState& state) const {
  for (const Level* level = state.level; level->parent != nullptr; level = level->parent) {
    const sdl::CompositeState* above = level->parent->composite;
    if (above != nullptr && above->is_aggregation) return {level->composite, level->parent};
  }
  return {nullptr, nullptr};
}

void Translator::input_transition(const std::string& state, const SignalInterface& p,
                                  const Handler& h) {
  const sdl::Input* input = h.input;
  const sdl::InputSignal* signal = h.signal;
  level_ = h.level;
  Chain chain{state, state + "/" + p.name, &p, {}, {}};
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
  if (input != nullptr && input->enabling) {
    std::optional<Scalar> guard = condition(*input->enabling, "an enabling condition");
    if (!guard) return;
    step.guard = guard->text;
    notes_.push_back("'" + p.name + "' waits in state " + state +
                     " while its enabling condition is false");
  }
  start_in_region(aggregation_, step, chain);
  if (input == nullptr) {
    terminate(std::move(step), state, chain);
    return;
  }
  chain_end(actions(input->transition.actions, 0, std::move(step), chain), input->at);
}

void Translator::fault_transition(const std::string& state, const SignalInterface& p,
                                  const Handler& h) {
  level_ = h.level;
  Chain chain{state, state + "/" + p.name + "/fault", nullptr, {}, {}};
  Step step{false, p.name + "_fault", state, "", {}};
  if (h.input->enabling) {
    std::optional<Scalar> guard = condition(*h.input->enabling, "an enabling condition");
    if (!guard) return;
    step.guard = guard->text;
  }
  start_in_region(aggregation_, step, chain);
  chain_end(actions(h.input->transition.actions, 0, std::move(step), chain), h.input->at);
}

void Translator::timer_transition(const std::string& state, const std::string& timer,
                                  const Handler& h) {
  const sdl::Input* input = h.input;
  level_ = h.level;
  Chain chain{state, state + "/" + timer, nullptr, {}, {}};
  Step step{false,
            timer + "_expired",
            state,
            timer + "_armed && " + timer + "_clock >= " + timer + "_value",
            {timer + "_armed = false;"}};
  if (input == nullptr) {
    if (aggregation_ != nullptr) step.guard += " && !" + aggregation_->busy;
    close(std::move(step), state);
    return;
  }
  start_in_region(aggregation_, step, chain);
  chain_end(actions(input->transition.actions, 0, std::move(step), chain), input->at);
}

void Translator::continuous_transitions(
    const StableState& state,
    const std::vector<std::pair<const sdl::State*, const Level*>>& blocks) {
  const std::string& place = state.place;
  struct Signal {
    std::int64_t priority;
    const sdl::ContinuousSignal* signal;
    const Level* level;
  };
  std::vector<Signal> signals;
  for (const auto& [s, level] : blocks) {
    for (const sdl::ContinuousSignal& c : s->continuous) {
      std::int64_t priority = std::numeric_limits<std::int64_t>::max();
      if (c.priority) {
        std::optional<std::int64_t> n = constant(*c.priority);
        if (!n) error(c.priority->at, "a priority that is not a constant is not translated");
        priority = n.value_or(priority);
      }
      signals.push_back(Signal{priority, &c, level});
    }
  }
  std::stable_sort(signals.begin(), signals.end(),
                   [](const Signal& a, const Signal& b) { return a.priority < b.priority; });
  std::string higher;
  for (std::size_t k = 0; k < signals.size(); ++k) {
    const sdl::ContinuousSignal& c = *signals[k].signal;
    level_ = signals[k].level;
    std::optional<Scalar> condition = this->condition(c.condition, "a continuous signal");
    if (!condition) continue;
    const std::string guard =
        higher.empty() ? condition->text : condition->text + " && !(" + higher + ")";
    higher += (higher.empty() ? "" : " || ") + condition->text;
    Chain chain{place, place + "/continuous" + std::to_string(k), nullptr, {}, {}};
    Step step = open(place, k, guard);
    start_in_region(aggregation_, step, chain);
    chain_end(actions(c.transition.actions, 0, std::move(step), chain), c.at);
  }
  if (!signals.empty()) {
    notes_.push_back("the continuous signals of state " + place +
                     " fire as soon as they hold (eager), before waiting calls");
  }
}

}  // namespace smcbip::taste2bip::detail
