// What a run shows to those who watch it (trace writers, the online monitors of smc): the state
// after each step, which item fired, and when. An observer may stop the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "bipc/ir/ir.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

struct Layout;
struct RunState;
class StringPool;

/// A read-only view of a run's state; valid only during the observer call that receives it.
class StateView {
 public:
  StateView(const bipc::ir::System& system, const Layout& layout, const RunState& state,
            const StringPool& strings);
  /// The same, given the state's data and marking (the engines' step loop has them at hand).
  StateView(const bipc::ir::System& system, const Layout& layout, const RunState& state,
            const StringPool& strings, const Val* data, const std::uint8_t* marking)
      : system_(system),
        layout_(layout),
        state_(state),
        strings_(strings),
        data_(data),
        marking_(marking) {}

  const bipc::ir::System& system() const { return system_; }
  TimeValue now() const;
  /// Whether place `place` of atom `atom` (indices into the IR) is marked.
  bool marked(bipc::ir::Index atom, bipc::ir::Index place) const;
  /// Data variable `slot` of atom `atom` (kind: the IR's declared type).
  Val data(bipc::ir::Index atom, bipc::ir::Index slot) const;
  /// Where data() and marked() read, the same in every state of the system's runs: a reader of
  /// many states finds them once, then reads data_at() and marked_at().
  std::size_t data_offset(bipc::ir::Index atom, bipc::ir::Index slot) const;
  std::size_t place_offset(bipc::ir::Index atom, bipc::ir::Index place) const;
  Val data_at(std::size_t offset) const { return data_[offset]; }
  bool marked_at(std::size_t offset) const { return marking_[offset] != 0; }
  /// Clock `clock` of atom `atom` now, in the clock's unit.
  double clock(bipc::ir::Index atom, bipc::ir::Index clock) const;
  /// The rate of that clock now (1 unless the model set another).
  double clock_rate(bipc::ir::Index atom, bipc::ir::Index clock) const;
  /// How fast that clock grows now: its rate, in its units per nanosecond.
  double clock_slope(bipc::ir::Index atom, bipc::ir::Index clock) const;
  /// The text of a string value.
  std::string_view text(Val v) const;
  /// The atom's full name as traces print it (`ROOT.a.b`).
  const std::string& atom_name(bipc::ir::Index atom) const;

 private:
  const bipc::ir::System& system_;
  const Layout& layout_;
  const RunState& state_;
  const StringPool& strings_;
  const Val* data_;
  const std::uint8_t* marking_;
};

/// The step that led to a state: the initial state is step 0 and fired nothing.
struct StepInfo {
  enum class Fired : std::uint8_t {
    Nothing,
    Interaction,
    Internal,
    External
  } fired = Fired::Nothing;
  std::uint64_t step = 0;
  TimeValue time = 0;
  bipc::ir::Index connector = bipc::ir::kNone;                     // Interaction
  bipc::ir::Index atom = bipc::ir::kNone, port = bipc::ir::kNone;  // Internal, External
};

/// How a run ended. Absorbing (SimulateOptions::stop_absorbing): items are still enabled but
/// none of them changes the places or data any more (clocks may still be reset).
enum class RunEnd : std::uint8_t { Deadlock, Timelock, Limit, Stopped, Error, Absorbing };

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// Called with the initial state, then after every step; returning false stops the run.
  virtual bool observe(const StepInfo& step, const StateView& state) = 0;
  /// Called once when the run ends (also when an observer stopped it); `message` names the
  /// error of an Error end, after its `file:line:column: ` in the model when known.
  virtual void finish(RunEnd /*end*/, int /*code*/, const std::string& /*message*/) {}
};

}  // namespace smcbip::engines
