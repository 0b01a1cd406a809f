// The offers of an interpreted atom kept by the values they depend on. When an atom type is a
// state machine whose labelled transitions are guarded by leading comparisons alone
// (data_guard.h: `sc < c`, `sc > 0 && ph == 1`), what its ports offer is a function of its
// marked place and of the data and parameters those comparisons read, and every offer is
// untimed. A step then looks its atom's offers up by those values instead of testing every
// transition again; a miss computes them and keeps them. Types without any comparison are left
// out: their offers cost less to find than to look up. A type whose values rarely repeat stops
// being kept: the offers are the same either way, only the time differs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/compiled_model.h"
#include "engines/api/model.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

class OfferMemo {
 public:
  OfferMemo(const bipc::ir::System& system, const Layout& layout);

  /// Whether the offers of atoms of `type` are looked up here.
  bool keeps(Index type) const { return types_[type].kept; }

  /// The kept offers of an atom of `type` (keeps(type)) in its state: written to `offers`
  /// (every port reset beforehand), with the value atom_offers returns in `result`; false when
  /// they are not kept yet (then `offers` is untouched).
  [[gnu::always_inline]] bool find(Index type, const std::uint8_t* marking, const Frame& f,
                                   std::optional<AtomPortValue>* offers, Index& result) {
    Type& t = types_[type];
    std::size_t e = 0;
    const Key key = key_of(t, marking, f, e);
    ++t.lookups;
    if (!t.filled[e] || !t.keys[e].same(key)) return false;
    ++t.hits;
    const Offered* offered = t.offered.data() + e * t.port_count;
    for (std::uint32_t p = 0; p < t.port_count; ++p) {
      if (offered[p].transition != bipc::ir::kNone) {
        offers[p] = AtomPortValue{offered[p].transition, {Interval::all(), offered[p].urgency}};
      }
    }
    result = t.results[e];
    return true;
  }

  /// Keeps the offers atom_offers computed for an atom of `type` (keeps(type)) in its state, and
  /// what it returned; every so many lookups, a type whose lookups mostly miss stops being kept.
  void remember(Index type, const std::uint8_t* marking, const Frame& f,
                const std::optional<AtomPortValue>* offers, Index result);

 private:
  /// The most values a key reads besides the place, and the most ports a kept type has.
  static constexpr std::size_t kMaxValues = 6;
  static constexpr std::uint32_t kMaxPorts = 16;
  static constexpr std::size_t kEntries = 256;  // per type; a power of two

  /// A value the offers of a place depend on: a data slot or a parameter of the atom.
  struct Read {
    LeadingTests::Base base = LeadingTests::kData;
    Index index = 0;
  };
  struct Key {
    std::uint32_t place = 0;
    std::array<std::int64_t, kMaxValues> values{};
    /// Every field compared, without branches (std::array's == calls memcmp).
    bool same(const Key& o) const {
      static_assert(kMaxValues == 6);
      return ((place ^ o.place) | (values[0] ^ o.values[0]) | (values[1] ^ o.values[1]) |
              (values[2] ^ o.values[2]) | (values[3] ^ o.values[3]) | (values[4] ^ o.values[4]) |
              (values[5] ^ o.values[5])) == 0;
    }
  };
  /// A port's offer: its transition (kNone: none), untimed.
  struct Offered {
    Index transition = bipc::ir::kNone;
    bipc::Urgency urgency = bipc::Urgency::Lazy;
  };
  struct Type {
    bool kept = false;
    std::uint32_t place_count = 0, port_count = 0;
    std::vector<std::vector<Read>> reads;  // per place
    std::vector<Key> keys;
    std::vector<std::uint8_t> filled;
    std::vector<Index> results;
    std::vector<Offered> offered;  // per entry, one per port
    std::uint64_t lookups = 0, hits = 0;
  };

  /// The key of an atom's state, and its entry in the table (`entry`).
  [[gnu::always_inline]] static Key key_of(const Type& t, const std::uint8_t* marking,
                                           const Frame& f, std::size_t& entry) {
    Key key;
    while (key.place + 1 < t.place_count && !marking[key.place]) ++key.place;
    const Val* const base[] = {f.atom_data, f.atom_params};  // LeadingTests::kData, kParams
    const Read* read = t.reads[key.place].data();
    const std::size_t count = t.reads[key.place].size();
    std::uint64_t h = key.place + 1;
    for (std::size_t k = 0; k < count; ++k, ++read) {
      key.values[k] = base[read->base][read->index].i;
      h = (h ^ static_cast<std::uint64_t>(key.values[k])) * 0x9E3779B97F4A7C15u;
    }
    entry = static_cast<std::size_t>((h ^ (h >> 29)) & (kEntries - 1));
    return key;
  }

  static Type type_of(const bipc::ir::System& system, const Layout& layout, Index type);

  std::vector<Type> types_;
};

}  // namespace smcbip::engines
