// One run of a model driven by its host, step by step: the host program owns the main loop
// (flight software embedding the C++ of `bipc gen`), reads and writes atom data, and feeds extern
// ports; the scheduling is Simulator's, so a run makes the same steps as `smcbip simulate` with
// the same seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "bipc/ir/ir.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/run_observer.h"
#include "engines/api/simulate.h"

namespace smcbip::engines {

/// What step() and run_until() did.
struct StepOutcome {
  /// Whether a step was executed (run_until: at least one); `info` is the (last) one.
  bool stepped = false;
  StepInfo info;
  /// Whether the run is over for now: `end` says how, `code` is its RunCode and `message` (valid
  /// as long as the execution) names an error. Deadlock, Timelock and Limit are the state's:
  /// write() or feed() may change it (the next step decides again). Error and Stopped are final.
  bool ended = false;
  RunEnd end = RunEnd::Deadlock;
  int code = kRunOk;
  std::string_view message;
};

/// An atom's data variable by IR indices (StateView::data's arguments).
struct DataSlot {
  bipc::ir::Index atom = bipc::ir::kNone, slot = bipc::ir::kNone;
};

/// An atom's port by IR indices (StepInfo's atom and port).
struct AtomPort {
  bipc::ir::Index atom = bipc::ir::kNone, port = bipc::ir::kNone;
};

/// One run of a model, driven by its host. Options are those of Simulator (engine, seed,
/// run_index, stochastic, asap, limit...); no trace is written: the host observes the run through
/// the outcomes, state() and an optional RunObserver. --interactive and --real-time are refused
/// (problem()): the host picks the dates, e.g. run_until(its clock).
///
/// Extern ports whose class (`as "<class>"`) `externs` registers pull their events from the
/// registered sources; the others are fed by the host (feed()), through a queue of
/// `fed_capacity` events per port allocated at construction.
///
/// Allocation: with the reference and optimised engines (untimed, timed or stochastic), once
/// the first steps have grown the buffers to the model's needs (the pool of interaction values
/// to the most values enabled at once, each value to the widest connector it served), step(),
/// run_until(), next_date(), read(), write() and feed() call no operator new, provided the
/// model's extern functions and registered port sources do not (the builtin printf builds
/// strings; a registered source returns its events by value unless it overrides pull()), nor
/// the observer. A run started again keeps the buffers; start() itself allocates. Not
/// allocation-free: the multithread engine (its pool); in stochastic mode, an interaction whose
/// ports bind several atom ports or sub-connectors, or whose connector defines more than 64
/// interactions, has its planned date kept in a hash map, which allocates when the item is
/// enabled anew; the message of an error.
class Execution {
 public:
  static constexpr std::size_t kDefaultFedCapacity = 64;

  /// Runs `model`; the model's own output (printf) goes to `model_output`. The model, `externs`
  /// and the stream must outlive the execution.
  Execution(const Model& model, const SimulateOptions& options, const Externs& externs,
            std::ostream& model_output, std::size_t fed_capacity = kDefaultFedCapacity);
  /// Runs the system interpreted from its IR (which must outlive the execution, as above).
  Execution(const bipc::ir::System& system, const SimulateOptions& options, const Externs& externs,
            std::ostream& model_output, std::size_t fed_capacity = kDefaultFedCapacity);
  ~Execution();
  Execution(const Execution&) = delete;
  Execution& operator=(const Execution&) = delete;

  /// Empty when the model can run; otherwise why not (start() then fails).
  const std::string& problem() const;
  /// The seed in use (drawn from the platform when the options have none).
  std::uint64_t seed() const;

  /// Starts run `run_index` of the seed (default: the options'): initial actions and resumes,
  /// step 0, which the observer sees. Called again, it starts a new run from the initial state
  /// that reuses the buffers the last one grew (what was decided, or pulled from a fed queue, is
  /// dropped; events still queued stay). False when the run cannot start: result() says why.
  bool start(std::optional<std::uint64_t> run_index = std::nullopt);
  /// Executes the next step: the one Simulator makes at this point, with the same random draws.
  StepOutcome step();
  /// Executes every step whose date is at most `t`, then lets time pass to `t` (now() == t)
  /// unless the run ended. The next step, decided but due after `t`, is kept: a run driven by
  /// many run_until calls makes the same steps as one driven by step() alone.
  StepOutcome run_until(TimeValue t);
  /// The date of the next step (deciding it if needed); nullopt when the run is over for now.
  std::optional<TimeValue> next_date();

  /// The model date the run has reached.
  TimeValue now() const;
  /// Steps executed so far.
  std::uint64_t steps() const;
  /// How the run ended, as Simulator::run reports it: the last end an outcome reported (a
  /// default result before any).
  const RunResult& result() const;
  /// The current state, once started (valid until the next call that changes it).
  StateView state() const;
  /// `observer` (or none) sees the initial state, every step, and each end the run reaches; its
  /// returning false stops the run.
  void set_observer(RunObserver* observer);

  /// A data variable by the atom's full name as traces print it (`ROOT.a.b`) and its name.
  std::optional<DataSlot> find_data(std::string_view atom, std::string_view data) const;
  /// A port by the atom's full name and the port's name.
  std::optional<AtomPort> find_port(std::string_view atom, std::string_view port) const;
  /// Data variable `slot` of atom `atom` (kind: the IR's declared type), once started.
  Val read(bipc::ir::Index atom, bipc::ir::Index slot) const;
  /// Sets a data variable as if the atom's own action had (its invariants are checked, its
  /// internal transitions run, its offers recomputed); the next step is decided again. False
  /// when the run is not going on (not started, or over for good) or the write ended it with
  /// an error (result()).
  bool write(bipc::ir::Index atom, bipc::ir::Index slot, Val value);
  /// Queues an event for a host-fed extern port, at model date `date` with the port type's
  /// parameter values; events of one port are taken in the order they are fed. The next step
  /// is decided again. False when the queue is full, the port is not fed by the host, or the
  /// values do not match its parameters.
  bool feed(bipc::ir::Index atom, bipc::ir::Index port, TimeValue date,
            std::span<const Val> values);

  struct State;  // defined in execution.cpp

 private:
  std::unique_ptr<State> state_;
};

}  // namespace smcbip::engines
