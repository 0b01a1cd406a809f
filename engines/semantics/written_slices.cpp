// The slices of the state a flat step may write, merged per position.
#include "engines/semantics/written_slices.h"

#include <algorithm>
#include <cstring>

#include "engines/semantics/copy_over.h"

namespace smcbip::engines {

namespace {

/// Sorts byte runs [first, first + size) and joins those that meet or overlap.
std::vector<std::pair<std::uint32_t, std::uint32_t>> merged(
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs) {
  std::sort(runs.begin(), runs.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [first, size] : runs) {
    if (size == 0) continue;
    if (!out.empty() && first <= out.back().first + out.back().second) {
      out.back().second = std::max(out.back().second, first + size - out.back().first);
    } else {
      out.emplace_back(first, size);
    }
  }
  return out;
}

}  // namespace

WrittenSlices::WrittenSlices(const FlatTables& t) : changing_(t.changing) {
  constexpr auto kVal = static_cast<std::uint32_t>(sizeof(Val));
  std::size_t largest = 0;
  first_slice_.push_back(0);
  first_changer_.push_back(0);
  for (std::uint32_t p = 0; p < t.positions(); ++p) {
    add_changers(t, p);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> data, places;
    const auto add_atom = [&](const FlatTables::Atom& atom) {
      data.emplace_back(atom.data * kVal, atom.data_size * kVal);
      places.emplace_back(atom.places, atom.place_count);
    };
    if (p < t.connectors.size()) {
      const FlatTables::Connector& c = t.connectors[p];
      data.emplace_back(c.data * kVal, c.data_size * kVal);
      for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) add_atom(t.ports[i].of);
    } else {
      add_atom(t.internal[p - t.connectors.size()].of);
    }
    std::size_t bytes = 0;
    for (const auto& [first, size] : merged(std::move(data))) {
      slices_.push_back({first, size, true});
      bytes += size;
    }
    for (const auto& [first, size] : merged(std::move(places))) {
      slices_.push_back({first, size, false});
      bytes += size;
    }
    first_slice_.push_back(static_cast<std::uint32_t>(slices_.size()));
    largest = std::max(largest, bytes);
  }
  before_.resize(largest);
}

void WrittenSlices::add_changers(const FlatTables& t, std::uint32_t p) {
  const auto add = [&](const FlatTables::AtomPort& port, std::uint8_t mask) {
    if (!port.of.has_internal_transitions) {
      changers_.push_back({port.offer, port.of.first_transition, mask});
    }
  };
  if (p >= t.connectors.size()) {
    add(t.internal[p - t.connectors.size()], FlatTables::kChanges);
  } else if (const FlatTables::Connector& c = t.connectors[p]; c.distinct_atoms && !c.triggered) {
    const std::uint8_t mask = c.has_down ? FlatTables::kChangesAfterDown : FlatTables::kChanges;
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) add(t.ports[i], mask);
  }
  first_changer_.push_back(static_cast<std::uint32_t>(changers_.size()));
}

const unsigned char* WrittenSlices::bytes_of(const RunState& state, const Slice& slice) {
  const unsigned char* base =
      slice.data ? reinterpret_cast<const unsigned char*>(state.data.data()) : state.marking.data();
  return base + slice.first;
}

void WrittenSlices::remember(const RunState& state, std::uint32_t p) {
  unsigned char* to = before_.data();
  for (std::uint32_t s = first_slice_[p]; s < first_slice_[p + 1]; ++s) {
    copy_bytes(to, bytes_of(state, slices_[s]), slices_[s].size);
    to += slices_[s].size;
  }
}

bool WrittenSlices::kept(const RunState& state, std::uint32_t p) const {
  const unsigned char* from = before_.data();
  for (std::uint32_t s = first_slice_[p]; s < first_slice_[p + 1]; ++s) {
    if (std::memcmp(from, bytes_of(state, slices_[s]), slices_[s].size) != 0) return false;
    from += slices_[s].size;
  }
  return true;
}

}  // namespace smcbip::engines
