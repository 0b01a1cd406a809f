#include "engines/api/run_observer.h"

#include "engines/interpreter/code_eval.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime.h"

namespace smcbip::engines {

StateView::StateView(const bipc::ir::System& system, const Layout& layout, const RunState& state,
                     const StringPool& strings)
    : StateView(system, layout, state, strings, state.data.data(), state.marking.data()) {}

TimeValue StateView::now() const { return state_.now; }

std::size_t StateView::data_offset(bipc::ir::Index atom, bipc::ir::Index slot) const {
  return layout_.atom_data[atom] + slot;
}

std::size_t StateView::place_offset(bipc::ir::Index atom, bipc::ir::Index place) const {
  return layout_.atom_places[atom] + place;
}

bool StateView::marked(bipc::ir::Index atom, bipc::ir::Index place) const {
  return state_.marking[layout_.atom_places[atom] + place] != 0;
}

Val StateView::data(bipc::ir::Index atom, bipc::ir::Index slot) const {
  return state_.data[layout_.atom_data[atom] + slot];
}

double StateView::clock(bipc::ir::Index atom, bipc::ir::Index clock) const {
  const std::size_t slot = layout_.atom_clocks[atom] + clock;
  return CodeEvaluator::clock_value(state_.clocks[slot], layout_.clock_units[slot], state_.now);
}

double StateView::clock_rate(bipc::ir::Index atom, bipc::ir::Index clock) const {
  return state_.clocks[layout_.atom_clocks[atom] + clock].rate;
}

double StateView::clock_slope(bipc::ir::Index atom, bipc::ir::Index clock) const {
  const std::size_t slot = layout_.atom_clocks[atom] + clock;
  return state_.clocks[slot].rate / static_cast<double>(layout_.clock_units[slot]);
}

std::string_view StateView::text(Val v) const { return strings_.text(v.s); }

const std::string& StateView::atom_name(bipc::ir::Index atom) const {
  return layout_.atom_names[atom];
}

}  // namespace smcbip::engines
