// Composite states flattened: entering one (`nextstate C [via E]`) goes to a place from which
// its substructure's start for that entry runs (after its `entry` procedure); `return [X]`
// inside it runs its `exit` procedure and then the `connect` transition of exit X.
#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

std::string Translator::entry_place(const sdl::CompositeState& c, const std::string& entry,
                                    const std::string& origin) {
  // One entry place per state entering it: while its start runs, that state stays marked.
  const std::string from = is_state_place(origin) ? origin : "";
  const auto key = std::make_pair(&c, folded(entry) + "|" + from);
  if (auto it = entry_places_.find(key); it != entry_places_.end()) return it->second;
  const Level* inner = composite_levels_.at(&c);
  std::string base = inner->prefix.substr(0, inner->prefix.size() - 1);
  if (!entry.empty()) base += "_via_" + bip_identifier(entry);
  if (!from.empty()) base += "_from_" + from;
  const std::string place = fresh(base);
  places_.push_back(place);
  entry_places_[key] = place;
  origin_of_[place] = from;
  pending_entries_.push_back(PendingEntry{&c, entry, place, from});
  notes_.push_back("entering nested state '" + c.name + "' (" + place +
                   "): its start runs after the return of the call that entered it");
  return place;
}

bool Translator::inline_hook(const sdl::Procedure* p, Step& step, Chain& chain,
                             const bipc::Location& at) {
  if (p == nullptr) return true;
  sdl::Action call;
  call.kind = sdl::Action::Kind::Call;
  call.name = p->name;
  call.at = at;
  Outcome unused;
  bool ended = false;
  return procedure_call(*p, call, step, chain, unused, ended) && !ended;
}

void Translator::translate_entries() {
  while (!pending_entries_.empty()) {
    const PendingEntry e = pending_entries_.back();
    pending_entries_.pop_back();
    const Level* inner = composite_levels_.at(e.composite);
    if (e.composite->is_aggregation) {
      enter_regions(e);
      continue;
    }
    const sdl::Start* start = nullptr;
    for (const sdl::Start& s : e.composite->body.starts) {
      if (folded(s.entry_point) == folded(e.entry)) start = &s;
    }
    if (start == nullptr) {
      error(e.composite->at, "nested state '" + e.composite->name + "' has no start" +
                                 (e.entry.empty() ? "" : " for entry point '" + e.entry + "'"));
      continue;
    }
    level_ = inner;
    Chain chain{e.origin, "entry/" + e.place, nullptr, {}, {}};
    Step step = open(e.place);
    if (!inline_hook(inner->entry, step, chain, start->at)) continue;
    chain_end(actions(start->transition.actions, 0, std::move(step), chain), start->at);
  }
}

void Translator::enter_regions(const PendingEntry& e) {
  const sdl::CompositeState& a = *e.composite;
  if (!e.entry.empty() || a.body.composite_states.empty()) {
    error(a.at, "state aggregation '" + a.name + "' is entered by its regions' starts only");
    return;
  }
  std::string to;
  for (const sdl::CompositeState& region : a.body.composite_states) {
    to += (to.empty() ? "" : ", ") + entry_place(region, "", "");
  }
  // One step marks a place of every region: the regions then run side by side.
  transitions_text_ += "    on " + branch_port(0) + " from " + e.place + " to " + to + " eager\n";
  notes_.push_back("the regions of state aggregation '" + a.name +
                   "' interleave their transitions; each call goes to the region that has an "
                   "input for it (else the first)");
}

const sdl::CompositeState* Translator::owner_region(const Level& aggregation,
                                                    const std::string& key) const {
  const sdl::CompositeState* first = nullptr;
  for (const sdl::CompositeState& region : aggregation.composite->body.composite_states) {
    first = first ? first : &region;
    if (has_input(region.body, key)) return &region;
  }
  return first;
}

bool Translator::has_input(const sdl::Body& body, const std::string& key) const {
  for (const sdl::State& s : body.states) {
    for (const sdl::Input& i : s.inputs) {
      for (const sdl::InputSignal& sig : i.signals) {
        if (signal_key(sig.name) == key) return true;
      }
    }
  }
  for (const sdl::CompositeState& c : body.composite_states) {
    if (has_input(c.body, key)) return true;
  }
  return false;
}

bool Translator::exit_composite(const sdl::Action& a, Step& step, Chain& chain, Outcome& out) {
  const Level* inner = level_;
  const sdl::CompositeState& c = *inner->composite;
  if (c.is_aggregation || (inner->parent->composite && inner->parent->composite->is_aggregation)) {
    error(a.at, "leaving a state aggregation or one of its regions is not translated");
    return false;
  }
  std::string exit;
  if (a.value && a.value->kind == sdl::Expr::Kind::Name) exit = folded(a.value->text);
  const sdl::ExitConnection* connection = nullptr;
  for (bool any : {false, true}) {
    for (const sdl::State& s : inner->parent->body->states) {
      if (connection != nullptr || s.is_any != any || !state_applies(s, folded(c.name))) continue;
      for (const sdl::ExitConnection& x : s.connections) {
        for (const std::string& point : x.exit_points) {
          if (folded(point) == exit || point == "*") connection = &x;
        }
        if (x.exit_points.empty() && exit.empty()) connection = &x;
      }
    }
  }
  if (connection == nullptr) {
    error(a.at, "no 'connect' of nested state '" + c.name + "' takes this return");
    return false;
  }
  if (!inline_hook(inner->exit, step, chain, a.at)) return false;
  level_ = inner->parent;
  out.merge(actions(connection->transition.actions, 0, std::move(step), chain));
  level_ = inner;
  return true;
}

}  // namespace smcbip::taste2bip::detail
