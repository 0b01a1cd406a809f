// The steps of a transition chain as BIP transitions: every step eager, so no time passes in an
// intermediate place unless the step waits for a synchronisation. In a process without nested
// states, while a transition runs, the place of the SDL state it started in stays marked
// (properties see SDL states only) and the `ready` place's token is taken (no other transition
// of the state may start):
//   state S to intermediate I:  from S, ready  to S, I
//   I to J:                     from I         to J
//   I (of S) to state T:        from S, I      to T, ready
//   state S to state T:         from S, ready  to T, ready
// Entering a nested state C from S goes on in C's entry place for S, from which C's start
// runs: S stays marked until that start reaches C's first substate. A process with a state
// aggregation has no `ready` (its regions run side by side).
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

bool Translator::is_return_port(const std::string& port) const {
  for (const SignalInterface& p : function_.provided) {
    if (port == p.name + "_return") return true;
  }
  for (const SignalInterface& r : function_.required) {
    if (r.synchronous() && port == r.name + "_result") return true;
  }
  return false;
}

bool Translator::is_fault_port(const std::string& port) const {
  if (!faults_only_) return false;
  for (const SignalInterface& p : function_.provided) {
    if (is_fault_interface(p) && port == p.name + "_fault") return true;
  }
  return false;
}

bool Translator::is_state_place(const std::string& place) const {
  for (const StableState& state : stable_) {
    if (state.place == place) return true;
  }
  return false;
}

std::string Translator::marking_from(const Step& step, const std::string& to) const {
  if (ready_place_.empty()) return step.from;
  if (is_state_place(step.from)) return step.from + ", " + ready_place_;
  const auto origin = origin_of_.find(step.from);
  const bool ends = is_state_place(to) || to == stop_place_;
  if (ends && origin != origin_of_.end() && !origin->second.empty()) {
    return origin->second + ", " + step.from;
  }
  return step.from;
}

std::string Translator::marking_to(const Step& step, const std::string& to) const {
  if (ready_place_.empty()) return to;
  if (is_state_place(to)) return to + ", " + ready_place_;
  if (!step.initial && is_state_place(step.from) && to != stop_place_) {
    return step.from + ", " + to;
  }
  return to;
}

void Translator::close(Step step, const std::string& to) {
  std::string text;
  if (step.initial) {
    text = "    initial to " + marking_to(step, to);
  } else {
    text =
        "    on " + step.port + " from " + marking_from(step, to) + " to " + marking_to(step, to);
    if (!step.guard.empty()) text += " provided (" + step.guard + ")";
    // A return (or a synchronous call's result) is lazy: the interface's wrapper, which joins
    // it, gives it its date (at once, or after the execution time of --wcet).
    // A fault is lazy too: it comes when it comes.
    if (!is_return_port(step.port) && !is_fault_port(step.port)) text += " eager";
  }
  if (!step.statements.empty()) {
    text += " do {";
    for (const std::string& s : step.statements) text += " " + s;
    text += " }";
  }
  transitions_text_ += text + "\n";
}

Step Translator::open(const std::string& from, std::size_t branch, std::string guard) {
  return Step{false, branch_port(branch), from, std::move(guard), {}};
}

std::string Translator::place(const Chain& chain) {
  const std::string base = chain.origin.empty() ? "START" : chain.origin;
  std::string name;
  do {
    name = base + "__" + std::to_string(++place_count_);
  } while (used_.count(name) > 0);
  reserve(name);
  places_.push_back(name);
  // A chain that starts in a nested state's entry place has no SDL state to keep marked.
  origin_of_[name] = is_state_place(chain.origin) ? chain.origin : "";
  return name;
}

std::string Translator::branch_port(std::size_t k) {
  std::string family;
  for (const Level* l = level_; l != nullptr && l->parent != nullptr; l = l->parent) {
    if (l->parent->composite != nullptr && l->parent->composite->is_aggregation) {
      family = l->prefix;
      break;
    }
  }
  std::vector<std::string>& ports = branch_ports_[family];
  while (ports.size() <= k) {
    const std::size_t n = ports.size();
    ports.push_back(fresh(family + (n == 0 ? "silent" : "silent_" + std::to_string(n))));
    port_order_.push_back(ports.back());
  }
  return ports[k];
}

void Translator::start_in_region(const Level* aggregation, Step& step, Chain& chain) const {
  if (aggregation == nullptr) return;
  chain.busy = aggregation->busy;
  step.guard = step.guard.empty() ? "!" + chain.busy : "(" + step.guard + ") && !" + chain.busy;
  step.statements.insert(step.statements.begin(), chain.busy + " = true;");
}

}  // namespace smcbip::taste2bip::detail
