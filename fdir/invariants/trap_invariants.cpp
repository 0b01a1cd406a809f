// The largest trap inside a set of places, by removing places until the trap condition holds.
#include "fdir/invariants/trap_invariants.h"

#include <deque>

namespace smcbip::fdir {

std::vector<Index> largest_trap(const PetriNet& net, const std::vector<std::uint8_t>& allowed) {
  std::vector<std::uint8_t> in(allowed);
  // Per transition, how many of its output places are still in the set; per place, the
  // transitions putting a token into it.
  std::vector<std::size_t> outputs_in(net.transitions.size(), 0);
  std::vector<std::vector<Index>> giving(net.places.size());
  for (Index t = 0; t < net.transitions.size(); ++t) {
    for (Index p : net.transitions[t].post) {
      outputs_in[t] += in[p] ? 1 : 0;
      giving[p].push_back(t);
    }
  }
  std::deque<Index> work;  // transitions that put nothing back into the set
  for (Index t = 0; t < net.transitions.size(); ++t) {
    if (outputs_in[t] == 0) work.push_back(t);
  }
  while (!work.empty()) {
    const Index t = work.front();
    work.pop_front();
    for (Index p : net.transitions[t].pre) {
      if (!in[p]) continue;
      in[p] = 0;  // t takes p's token and puts none back: p belongs to no trap inside the set
      for (Index u : giving[p]) {
        if (--outputs_in[u] == 0) work.push_back(u);
      }
    }
  }
  std::vector<Index> trap;
  for (Index p = 0; p < in.size(); ++p) {
    if (in[p]) trap.push_back(p);
  }
  return trap;
}

std::optional<std::vector<Index>> excluding_trap(const PetriNet& net,
                                                 const std::vector<std::uint8_t>& marking) {
  std::vector<std::uint8_t> unmarked(marking.size());
  for (std::size_t p = 0; p < marking.size(); ++p) unmarked[p] = marking[p] ? 0 : 1;
  std::vector<Index> trap = largest_trap(net, unmarked);
  for (Index p : trap) {
    if (net.initial[p]) return trap;
  }
  return std::nullopt;
}

}  // namespace smcbip::fdir
