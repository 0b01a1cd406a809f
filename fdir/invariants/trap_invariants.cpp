// The largest trap inside a set of places, by removing places until the trap condition holds.
#include "fdir/invariants/trap_invariants.h"

#include <algorithm>
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

std::vector<Index> trap_around(const PetriNet& net, const std::vector<std::uint8_t>& within,
                               Index place) {
  std::vector<std::uint8_t> in(net.places.size(), 0);
  in[place] = 1;
  std::vector<Index> trap{place};
  for (bool grown = true; grown;) {
    grown = false;
    for (const NetTransition& t : net.transitions) {
      bool takes = false, puts = false;
      for (Index p : t.pre) takes = takes || in[p];
      for (Index p : t.post) puts = puts || in[p];
      if (!takes || puts) continue;
      for (Index p : t.post) {
        if (within[p] && !in[p]) in[p] = 1, trap.push_back(p);
      }
      grown = true;
    }
  }
  std::sort(trap.begin(), trap.end());
  return trap;
}

std::vector<std::vector<Index>> excluding_traps(const PetriNet& net,
                                                const std::vector<std::uint8_t>& marking,
                                                std::size_t limit) {
  std::vector<std::uint8_t> unmarked(marking.size());
  for (std::size_t p = 0; p < marking.size(); ++p) unmarked[p] = marking[p] ? 0 : 1;
  std::vector<std::uint8_t> largest(marking.size(), 0);
  for (Index p : largest_trap(net, unmarked)) largest[p] = 1;
  std::vector<std::vector<Index>> traps;
  std::vector<std::uint8_t> covered(marking.size(), 0);
  for (Index p = 0; p < largest.size() && traps.size() < limit; ++p) {
    if (!largest[p] || !net.initial[p] || covered[p]) continue;
    traps.push_back(trap_around(net, largest, p));
    for (Index q : traps.back()) covered[q] = 1;
  }
  return traps;
}

}  // namespace smcbip::fdir
