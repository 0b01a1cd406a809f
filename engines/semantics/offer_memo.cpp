#include "engines/semantics/offer_memo.h"

#include <algorithm>

namespace smcbip::engines {

OfferMemo::OfferMemo(const bipc::ir::System& system, const Layout& layout) {
  for (Index type = 0; type < system.atom_types.size(); ++type) {
    types_.push_back(type_of(system, layout, type));
  }
}

OfferMemo::Type OfferMemo::type_of(const bipc::ir::System& system, const Layout& layout,
                                   Index type) {
  Type t;
  const bipc::ir::AtomType& atom_type = system.atom_types[type];
  const auto& from_place = layout.labelled_from_place[type];
  if (from_place.empty() || atom_type.ports.size() > kMaxPorts) return t;
  for (const std::vector<TransitionEntry>& entries : from_place) {
    std::vector<Read>& reads = t.reads.emplace_back();
    for (const TransitionEntry& entry : entries) {
      // Offers that interpreted code decides (or whose window a clock may cut) are not kept.
      if (!atom_type.transitions[entry.transition].guard.empty() && !entry.leading_whole) {
        return Type{};
      }
      if (entry.leading == bipc::ir::kNone) continue;
      const LeadingTests& tests = layout.leading_tests[entry.leading];
      for (std::size_t k = 0; k < tests.count; ++k) {
        const LeadingTests::Test& test = tests.tests[k];
        for (const Read read :
             {Read{test.left_base, test.left}, Read{test.right_base, test.right}}) {
          if (read.base == LeadingTests::kLiterals) continue;
          const bool known = std::any_of(reads.begin(), reads.end(), [&](const Read& r) {
            return r.base == read.base && r.index == read.index;
          });
          if (!known) reads.push_back(read);
        }
      }
    }
    if (reads.size() > kMaxValues) return Type{};
  }
  // Without a comparison, finding the transitions of the marked place costs less than a look-up.
  const bool compares = std::any_of(t.reads.begin(), t.reads.end(),
                                    [](const std::vector<Read>& reads) { return !reads.empty(); });
  if (!compares) return Type{};
  t.kept = true;
  t.place_count = static_cast<std::uint32_t>(from_place.size());
  t.port_count = static_cast<std::uint32_t>(atom_type.ports.size());
  t.keys.resize(kEntries);
  t.filled.assign(kEntries, 0);
  t.results.assign(kEntries, bipc::ir::kNone);
  t.offered.resize(kEntries * t.port_count);
  return t;
}

void OfferMemo::remember(Index type, const std::uint8_t* marking, const Frame& f,
                         const std::optional<AtomPortValue>* offers, Index result) {
  Type& t = types_[type];
  // Judged every so many lookups: a type whose values rarely repeat pays for keeping them.
  constexpr std::uint64_t kJudgedEvery = 4096;
  if (t.lookups >= kJudgedEvery) {
    if (t.hits * 2 < t.lookups) {
      t = Type{};
      return;
    }
    t.lookups = t.hits = 0;
  }
  std::size_t e = 0;
  const Key key = key_of(t, marking, f, e);
  t.keys[e] = key;
  t.filled[e] = 1;
  t.results[e] = result;
  Offered* offered = t.offered.data() + e * t.port_count;
  for (std::uint32_t p = 0; p < t.port_count; ++p) {
    offered[p] =
        offers[p] ? Offered{offers[p]->transition, offers[p]->constraint.urgency} : Offered{};
  }
}

}  // namespace smcbip::engines
