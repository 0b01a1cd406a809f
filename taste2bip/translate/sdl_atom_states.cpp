// SDL states as places and what happens in them: the start transition, each provided
// interface's call (handled by an input, by `input *`, consumed implicitly, or saved), timer
// expiries and continuous signals.
#include <algorithm>
#include <limits>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

void Translator::add_state(const std::string& name) {
  const std::string f = folded(name);
  if (name == "-" || states_.count(f) > 0) return;
  std::string place = bip_identifier(name);
  if (used_.count(place) > 0) {
    place = fresh(place + "_state");
    notes_.push_back("state '" + name + "' is the place " + place + " (its name is taken)");
  }
  reserve(place);
  states_[f] = place;
  state_order_.push_back(f);
  places_.push_back(place);
}

void Translator::scan_nextstates(const std::vector<sdl::Action>& list) {
  for (const sdl::Action& a : list) {
    if (a.kind == sdl::Action::Kind::NextState) add_state(a.name);
    if (a.kind == sdl::Action::Kind::Decision) {
      for (const sdl::Answer& answer : a.decision.answers) {
        scan_nextstates(answer.transition.actions);
      }
    }
  }
}

void Translator::collect_states() {
  for (const sdl::State& s : process_.body.states) {
    for (const std::string& n : s.names) add_state(n);
  }
  for (const sdl::Start& s : process_.body.starts) scan_nextstates(s.transition.actions);
  for (const sdl::FloatingLabel& l : process_.body.labels) scan_nextstates(l.transition.actions);
  for (const sdl::State& s : process_.body.states) {
    for (const sdl::Input& i : s.inputs) scan_nextstates(i.transition.actions);
    for (const sdl::ContinuousSignal& c : s.continuous) scan_nextstates(c.transition.actions);
  }
}

void Translator::collect_labels(const std::vector<sdl::Action>& list, bool top_level,
                                std::map<std::string, LabelSite>& into) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    const sdl::Action& a = list[i];
    if (a.kind == sdl::Action::Kind::Label)
      into[folded(a.name)] = LabelSite{&list, i + 1, top_level};
    if (a.kind == sdl::Action::Kind::Decision) {
      for (const sdl::Answer& answer : a.decision.answers) {
        collect_labels(answer.transition.actions, false, into);
      }
    }
  }
}

void Translator::chain_end(const Outcome& outcome, const bipc::Location& at) {
  if (!outcome.falls.empty()) {
    error(at, "a transition that ends without nextstate, join or stop is not translated");
  }
}

void Translator::translate_start() {
  const sdl::Start* start = nullptr;
  for (const sdl::Start& s : process_.body.starts) {
    if (!s.entry_point.empty()) {
      error(s.at, "start of entry point '" + s.entry_point + "' is not translated");
    } else if (start != nullptr) {
      error(s.at, "a second start transition");
    } else {
      start = &s;
    }
  }
  if (start == nullptr) {
    error(process_.at, "process '" + process_.name + "' has no start transition");
    return;
  }
  Chain chain{"", "start", nullptr, {}};
  Step step{true, "", "", "", initial_statements_};
  chain_end(actions(start->transition.actions, 0, std::move(step), chain), start->at);
}

bool Translator::state_applies(const sdl::State& s, const std::string& state) const {
  if (!s.is_any) {
    return std::any_of(s.names.begin(), s.names.end(),
                       [&](const std::string& n) { return folded(n) == state; });
  }
  return std::none_of(s.except.begin(), s.except.end(),
                      [&](const std::string& n) { return folded(n) == state; });
}

}  // namespace smcbip::taste2bip::detail
