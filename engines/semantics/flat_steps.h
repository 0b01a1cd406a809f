// The compiled step path: the optimised engine's steps on the systems flat_tables covers, over a
// model's code known at compile time. Instantiated by generated code on its own (final) code
// class, every call into the model's guards, actions and atom steps is direct and may be
// inlined, and the step keeps to compact tables: what a step costs is the atoms it fires and
// the connectors next to them.
//
// It makes the Runtime's and Scheduler's choices with the same draws: items at positions (the
// listed connectors in listing order, then the internal ports) counted in an ItemIndex, the
// choice of choose_in_shared_window, then the firing of Runtime::execute_value and fire_port.
// Whatever the Runtime would report as an error (1-safety, non-determinism, code faults) ends
// the path as Beyond: the engines then replay the run, which tells the error as they do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/interpreter/code_eval.h"
#include "engines/model.h"
#include "engines/run_observer.h"
#include "engines/semantics/flat_tables.h"
#include "engines/semantics/item_index.h"
#include "engines/semantics/layout.h"
#include "engines/semantics/runtime.h"
#include "engines/semantics/shared_window.h"
#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

/// `Code`: the model's ModelCode class, final so that its calls bind statically.
template <class Code>
class FlatSteps final : public CompiledSteps {
 public:
  FlatSteps(Code& code, const bipc::ir::System& system, const Layout& layout, FlatTables tables)
      : code_(code), system_(system), layout_(layout), t_(std::move(tables)) {
    offers_.resize(t_.offer_count);
    value_data_.resize(t_.value_data_size);
    touched_.assign(t_.atoms.size(), 0);
    recomputed_.assign(t_.positions(), 0);
  }

  bool begin(RunState& state, RandomStream& random, bool asap, bool first_enabled) override {
    state_ = &state;
    random_ = &random;
    asap_ = asap;
    first_enabled_ = first_enabled;
    index_.reset(t_.positions());
    eager_.assign(t_.positions(), 0);
    eager_count_ = 0;
    try {
      for (Index a = 0; a < t_.atoms.size(); ++a) {
        if (!update_atom(a, atom_frame(a))) return false;
      }
      for (std::uint32_t p = 0; p < t_.positions(); ++p) recompute(p);
    } catch (const CodeFault&) {
      return false;
    }
    return true;
  }

  Outcome step(bool at_limit, StepInfo& info) override {
    const std::size_t n = index_.total();
    if (n == 0) return Outcome::Deadlock;
    if (at_limit) return Outcome::Limit;
    const SharedWindowChoice choice =
        choose_in_shared_window(n, state_->now, eager_count_ == 0, asap_, first_enabled_, *random_);
    const std::size_t p = index_.find(choice.chosen).first;
    state_->now = choice.date;
    info = StepInfo{};
    info.time = choice.date;
    ++stamp_;
    touched_list_.clear();
    try {
      if (p < t_.connectors.size()) {
        info.fired = StepInfo::Fired::Interaction;
        info.connector = t_.connectors[p].index;
        if (!fire_connector(t_.connectors[p])) return Outcome::Beyond;
      } else {
        const FlatTables::Internal& internal = t_.internal[p - t_.connectors.size()];
        info.fired = StepInfo::Fired::Internal;
        info.atom = internal.atom;
        info.port = internal.port;
        if (!fire_port(internal.atom, internal.port)) return Outcome::Beyond;
      }
      for (Index a : touched_list_) {
        const FlatTables::Atom& atom = t_.atoms[a];
        for (std::uint32_t i = atom.first_neighbour; i < atom.neighbours_end; ++i) {
          const std::uint32_t q = t_.neighbours[i];
          if (recomputed_[q] == stamp_) continue;
          recomputed_[q] = stamp_;
          recompute(q);
        }
      }
    } catch (const CodeFault&) {
      return Outcome::Beyond;
    }
    return Outcome::Fired;
  }

 private:
  /// What connector code finds its port parameters through (Frame::port_slot).
  struct PortContext {
    FlatSteps* steps;
    const FlatTables::Connector* connector;
  };
  static Val* port_slot(const void* context, Index port, std::uint16_t arg) {
    const auto& c = *static_cast<const PortContext*>(context);
    const FlatTables& t = c.steps->t_;
    const FlatTables::Port& bound = t.ports[c.connector->first_port + port];
    return &c.steps->state_->data[t.param_slots[bound.first_param + arg]];
  }

  Frame atom_frame(Index a) {
    const FlatTables::Atom& atom = t_.atoms[a];
    Frame f;
    f.atom_data = state_->data.data() + atom.data;
    f.atom_params = layout_.params.data() + atom.params;
    f.clock_units = layout_.clock_units.data() + atom.clocks;
    f.now = state_->now;
    return f;
  }

  Frame connector_frame(const FlatTables::Connector& c, const PortContext& context) {
    Frame f;
    f.connector_data = value_data_.data() + c.value_data;
    f.port_slot = &port_slot;
    f.port_context = &context;
    f.now = state_->now;
    return f;
  }

  const bipc::ir::InteractionCode& interaction(const FlatTables::Connector& c) const {
    return system_.connector_types[c.type].interactions[static_cast<std::size_t>(c.code)];
  }

  /// Runtime::update_atom for a covered atom: its offers afresh; false on a non-deterministic
  /// choice.
  bool update_atom(Index a, const Frame& f) {
    const FlatTables::Atom& atom = t_.atoms[a];
    std::optional<AtomPortValue>* offers = offers_.data() + atom.first_offer;
    const std::size_t ports = system_.atom_types[atom.type].ports.size();
    for (std::size_t p = 0; p < ports; ++p) offers[p].reset();
    return code_.atom_offers(atom.type, state_->marking.data() + atom.places, f, offers) ==
           bipc::ir::kNone;
  }

  /// Runtime::fire_port: the offered transition, the internal transitions it enables, the new
  /// offers; false where the Runtime reports an error.
  bool fire_port(Index a, Index port) {
    const FlatTables::Atom& atom = t_.atoms[a];
    const std::optional<AtomPortValue>& offer = offers_[atom.first_offer + port];
    if (!offer) return true;
    if (touched_[a] != stamp_) {
      touched_[a] = stamp_;
      touched_list_.push_back(a);
    }
    const Frame f = atom_frame(a);
    std::uint8_t* marking = state_->marking.data() + atom.places;
    if (!code_.atom_fire(atom.type, offer->transition, marking, f)) return false;
    if (atom.has_internal_transitions) {
      for (;;) {
        const Index t = code_.atom_internal(atom.type, marking, f);
        if (t == bipc::ir::kNone) break;
        if (t == ModelCode::kSeveralTransitions || !code_.atom_fire(atom.type, t, marking, f)) {
          return false;
        }
      }
    }
    return update_atom(a, f);
  }

  /// Runtime::execute_value for a rendezvous: `down` over the value, its data written back, then
  /// the ports in parameter order.
  bool fire_connector(const FlatTables::Connector& c) {
    if (c.has_down) {
      const PortContext context{this, &c};
      code_.execute(interaction(c).down, connector_frame(c, context));
    }
    std::copy_n(value_data_.begin() + c.value_data, c.data_size, state_->data.begin() + c.data);
    for (std::uint32_t i = c.first_port; i < c.ports_end; ++i) {
      if (!fire_port(t_.ports[i].atom, t_.ports[i].port)) return false;
    }
    return true;
  }

  /// The item at position `p` as the Runtime computes it: a connector's value when all its ports
  /// offer and its guard holds (then its `up` runs), an internal port's offer.
  void recompute(std::uint32_t p) {
    bool enabled = true;
    bool eager = false;
    if (p < t_.connectors.size()) {
      const FlatTables::Connector& c = t_.connectors[p];
      for (std::uint32_t i = c.first_port; i < c.ports_end && enabled; ++i) {
        const std::optional<AtomPortValue>& offer = offers_[t_.ports[i].offer];
        enabled = offer.has_value();
        eager = eager || (enabled && offer->constraint.urgency == bipc::Urgency::Eager);
      }
      if (enabled) enabled = value_allowed(c);
    } else {
      const std::optional<AtomPortValue>& offer =
          offers_[t_.internal[p - t_.connectors.size()].offer];
      enabled = offer.has_value();
      eager = enabled && offer->constraint.urgency == bipc::Urgency::Eager;
    }
    index_.set(p, enabled ? 1 : 0);
    const bool now_eager = enabled && eager;
    if (now_eager != static_cast<bool>(eager_[p])) {
      eager_[p] = now_eager;
      eager_count_ += now_eager ? 1 : -1;
    }
  }

  /// Runtime::connector_code_allows: the connector's data copied into its value, the guard, then
  /// `up` when it holds.
  bool value_allowed(const FlatTables::Connector& c) {
    std::copy_n(state_->data.begin() + c.data, c.data_size, value_data_.begin() + c.value_data);
    if (!c.guarded) return true;
    const PortContext context{this, &c};
    const Frame f = connector_frame(c, context);
    const bipc::ir::InteractionCode& code = interaction(c);
    if (!code.guard.empty() && !code_.evaluate(code.guard, f).b) return false;
    code_.execute(code.up, f);
    return true;
  }

  Code& code_;
  const bipc::ir::System& system_;
  const Layout& layout_;
  const FlatTables t_;
  RunState* state_ = nullptr;
  RandomStream* random_ = nullptr;
  bool asap_ = false, first_enabled_ = false;
  std::vector<std::optional<AtomPortValue>> offers_;
  std::vector<Val> value_data_;
  ItemIndex index_;
  std::vector<std::uint8_t> eager_;  // per position: its item is enabled and eager
  std::ptrdiff_t eager_count_ = 0;
  // The atoms a step fired, and the positions it recomputed, marked by the step's stamp.
  std::uint64_t stamp_ = 0;
  std::vector<std::uint64_t> touched_, recomputed_;
  std::vector<Index> touched_list_;
};

/// The compiled step path over `code` for `system`, or nullptr when flat_tables does not cover
/// it.
template <class Code>
std::unique_ptr<CompiledSteps> make_flat_steps(Code& code, const bipc::ir::System& system,
                                               const Layout& layout) {
  std::optional<FlatTables> tables = flat_tables(system, layout, code);
  if (!tables) return nullptr;
  return std::make_unique<FlatSteps<Code>>(code, system, layout, std::move(*tables));
}

}  // namespace smcbip::engines
