// SDL states as places: the states of the process and, flattened, those of its composite
// states' substructures (`<Composite>_<Sub>`); the start transition.
#include <algorithm>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

void Translator::add_state(Level& level, const std::string& name) {
  const std::string f = folded(name);
  if (name == "-" || level.states.count(f) > 0 || level.composites.count(f) > 0) return;
  std::string place = bip_identifier(level.prefix + name);
  if (used_.count(place) > 0) {
    place = fresh(place + "_state");
    notes_.push_back("state '" + name + "' is the place " + place + " (its name is taken)");
  }
  reserve(place);
  level.states[f] = place;
  stable_.push_back(StableState{place, f, &level});
  places_.push_back(place);
}

void Translator::scan_nextstates(Level& level, const std::vector<sdl::Action>& list) {
  for (const sdl::Action& a : list) {
    if (a.kind == sdl::Action::Kind::NextState) add_state(level, a.name);
    if (a.kind == sdl::Action::Kind::Decision) {
      for (const sdl::Answer& answer : a.decision.answers) {
        scan_nextstates(level, answer.transition.actions);
      }
    }
  }
}

Level* Translator::build_level(const sdl::Body& body, const std::string& prefix,
                               const Level* parent, const sdl::CompositeState* composite) {
  levels_.push_back(std::make_unique<Level>());
  Level& level = *levels_.back();
  level.body = &body;
  level.prefix = prefix;
  level.parent = parent;
  level.composite = composite;
  for (const sdl::CompositeState& c : body.composite_states) {
    if (c.is_aggregation && !c.body.states.empty() &&
        std::any_of(c.body.states.begin(), c.body.states.end(), [&](const sdl::State& s) {
          return !s.inputs.empty() || !s.continuous.empty();
        })) {
      error(c.at, "state aggregation '" + c.name +
                      "' with transitions of its own (besides its "
                      "regions') is not translated");
    }
    level.composites[folded(c.name)] = &c;
  }
  for (const sdl::State& s : body.states) {
    for (const std::string& n : s.names) add_state(level, n);
  }
  for (const sdl::Start& s : body.starts) scan_nextstates(level, s.transition.actions);
  for (const sdl::FloatingLabel& l : body.labels) scan_nextstates(level, l.transition.actions);
  for (const sdl::State& s : body.states) {
    for (const sdl::Input& i : s.inputs) scan_nextstates(level, i.transition.actions);
    for (const sdl::ContinuousSignal& c : s.continuous)
      scan_nextstates(level, c.transition.actions);
    for (const sdl::ExitConnection& c : s.connections) scan_nextstates(level, c.transition.actions);
  }
  if (composite != nullptr) declare_level(level);
  if (composite != nullptr && composite->is_aggregation) {
    level.busy = fresh(prefix + "busy");
    data_text_ += "    data bool " + level.busy + " = false\n";
  }
  for (const sdl::CompositeState& c : body.composite_states) {
    composite_levels_[&c] = build_level(c.body, prefix + bip_identifier(c.name) + "_", &level, &c);
  }
  return &level;
}

void Translator::declare_level(Level& level) {
  const sdl::Body& body = *level.body;
  for (const sdl::Variable& v : body.variables) {
    if (scopes_.front().count(folded(v.name)) > 0) {
      error(v.at, "variable '" + v.name + "' is declared twice (SDL names ignore case)");
      continue;
    }
    std::optional<Ref> ref = declare_sdl_variable(v, level.prefix);
    if (!ref) continue;
    scopes_.front()[folded(v.name)] = Binding{*ref, 0};
    if (v.initial) assign(*ref, *v.initial, initial_statements_);
  }
  for (const sdl::Timer& t : body.timers) {
    error(t.at, "timer '" + t.name + "' declared in a substructure is not translated");
  }
  for (const sdl::Procedure& p : body.procedures) {
    if (folded(p.name) == "entry") level.entry = &p;
    if (folded(p.name) == "exit") level.exit = &p;
    if (level.entry != &p && level.exit != &p) procedures_[folded(p.name)].push_back(&p);
    declare_procedure(p, level.prefix);
  }
}

void Translator::collect_labels(const std::vector<sdl::Action>& list, bool top_level,
                                std::map<std::string, LabelSite>& into) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    const sdl::Action& a = list[i];
    if (a.kind == sdl::Action::Kind::Label) {
      into[folded(a.name)] = LabelSite{&list, i + 1, top_level};
    }
    if (a.kind == sdl::Action::Kind::Decision) {
      for (const sdl::Answer& answer : a.decision.answers) {
        collect_labels(answer.transition.actions, false, into);
      }
    }
  }
}

void Translator::collect_body_labels(const sdl::Body& body,
                                     std::map<std::string, LabelSite>& into) {
  for (const sdl::FloatingLabel& l : body.labels) {
    into[folded(l.name)] = LabelSite{&l.transition.actions, 0, true};
    collect_labels(l.transition.actions, true, into);
  }
  for (const sdl::Start& s : body.starts) collect_labels(s.transition.actions, true, into);
  for (const sdl::State& s : body.states) {
    for (const sdl::Input& i : s.inputs) collect_labels(i.transition.actions, true, into);
    for (const sdl::ContinuousSignal& c : s.continuous) {
      collect_labels(c.transition.actions, true, into);
    }
    for (const sdl::ExitConnection& c : s.connections) {
      collect_labels(c.transition.actions, true, into);
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
      error(s.at, "start of entry point '" + s.entry_point + "' outside a nested state");
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
  level_ = levels_.front().get();
  Chain chain{"", "start", nullptr, {}, {}};
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

std::vector<std::pair<const sdl::State*, const Level*>> Translator::blocks_of(
    const StableState& s) const {
  std::vector<std::pair<const sdl::State*, const Level*>> blocks;
  std::string name = s.name;
  for (const Level* level = s.level; level != nullptr; level = level->parent) {
    for (bool any : {false, true}) {
      for (const sdl::State& b : level->body->states) {
        if (b.is_any == any && state_applies(b, name)) blocks.emplace_back(&b, level);
      }
    }
    if (level->composite != nullptr) name = folded(level->composite->name);
  }
  return blocks;
}

}  // namespace smcbip::taste2bip::detail
