// The steps of a transition chain as BIP transitions: every step eager, so no time passes in an
// intermediate place unless the step waits for a synchronisation.
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip::detail {

void Translator::close(Step step, const std::string& to) {
  std::string text;
  if (step.initial) {
    text = "    initial to " + to;
  } else {
    text = "    on " + step.port + " from " + step.from + " to " + to;
    if (!step.guard.empty()) text += " provided (" + step.guard + ")";
    text += " eager";
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
