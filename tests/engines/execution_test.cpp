// The host-driven Execution: stepped to its end it makes Simulator's steps with the same seed
// (models of models/, and conformance models interpreted and generated; reference and optimised
// engines); run_until slices make the same steps; a started-over run is a fresh one; host
// writes, fed extern ports and errors.
#include "engines/api/execution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "tests/engines/conformance_externs.h"
#include "tests/engines/generated_conformance.h"
#include "tests/engines/temp_model.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::Execution;
using engines::RunEnd;
using engines::StepInfo;
using engines::StepOutcome;

/// A step as a line of text, so that a difference prints readably.
std::string step_text(const StepInfo& step) {
  std::ostringstream out;
  out << "#" << step.step << " at " << step.time << ": ";
  switch (step.fired) {
    case StepInfo::Fired::Nothing:
      out << "initial";
      break;
    case StepInfo::Fired::Interaction:
      out << "connector " << step.connector;
      break;
    case StepInfo::Fired::Internal:
    case StepInfo::Fired::External:
      out << (step.fired == StepInfo::Fired::Internal ? "internal " : "external ") << step.atom
          << "." << step.port;
      break;
  }
  return out.str();
}

/// The whole state as text: date, every atom's marking and data.
std::string state_text(const engines::StateView& state) {
  const bipc::ir::System& system = state.system();
  std::ostringstream out;
  out << "now " << state.now();
  for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    out << "\n" << state.atom_name(a) << ":";
    for (bipc::ir::Index p = 0; p < type.places.size(); ++p)
      out << (state.marked(a, p) ? "1" : "0");
    for (bipc::ir::Index d = 0; d < type.data.size(); ++d) out << " " << state.data(a, d).s;
  }
  return out.str();
}

/// What a run showed its observer: every step, the last state, how it ended.
struct Recording : engines::RunObserver {
  std::vector<std::string> steps;
  std::string last_state;
  RunEnd end = RunEnd::Stopped;
  int code = -1;
  std::size_t finishes = 0;

  bool observe(const StepInfo& step, const engines::StateView& state) override {
    steps.push_back(step_text(step));
    last_state = state_text(state);
    return true;
  }
  void finish(RunEnd run_end, int run_code, const std::string& /*message*/) override {
    end = run_end;
    code = run_code;
    ++finishes;
  }
};

/// The builtins and the conformance suite's externs (executions keep pointers into them).
const engines::Externs& test_externs() {
  static const engines::Externs externs = [] {
    engines::Externs result = engines::Externs::with_builtins();
    register_conformance_externs(result);
    return result;
  }();
  return externs;
}

Recording simulator_run(const engines::Model& model, const engines::SimulateOptions& options) {
  std::ostringstream out;
  engines::Simulator simulator(model, options, test_externs());
  Recording recording;
  simulator.run(options.run_index, engines::RunStreams{out, out}, &recording);
  return recording;
}

/// Execution stepped until the run ends; its outcomes must agree with what it observed.
Recording stepped_run(Execution& execution, std::optional<std::uint64_t> run_index = {}) {
  Recording recording;
  execution.set_observer(&recording);
  if (!execution.start(run_index)) return recording;
  for (;;) {
    const StepOutcome outcome = execution.step();
    if (outcome.ended) {
      EXPECT_EQ(outcome.end, recording.end);
      EXPECT_EQ(outcome.code, recording.code);
      break;
    }
    EXPECT_TRUE(outcome.stepped);
    EXPECT_EQ(step_text(outcome.info), recording.steps.back());
  }
  // Asking again changes nothing.
  EXPECT_TRUE(execution.step().ended);
  EXPECT_EQ(recording.finishes, 1u);
  return recording;
}

void expect_same_run(const Recording& actual, const Recording& expected) {
  EXPECT_EQ(actual.steps, expected.steps);
  EXPECT_EQ(actual.last_state, expected.last_state);
  EXPECT_EQ(actual.end, expected.end);
  EXPECT_EQ(actual.code, expected.code);
}

engines::SimulateOptions options_of(engines::EngineKind engine, std::uint64_t seed) {
  engines::SimulateOptions options;
  options.engine = engine;
  options.seed = seed;
  options.silent = true;
  options.limit = 1500;
  return options;
}

struct ModelCase {
  const char* file;  // under models/
  const char* root;
};

constexpr ModelCase kModels[] = {
    {"channel.bip", "System()"},
    {"families/rendezvous_10.bip", "Top()"},
    {"families/priorities_10.bip", "Top()"},
    {"rover_watchdog.bip", "RoverSystem()"},
    {"two_exponentials.bip", "System()"},
};

/// Calls `check(system, file)` for each model of kModels; stops at the first failure.
template <class Check>
void for_each_model(Check check) {
  for (const ModelCase& c : kModels) {
    const std::optional<bipc::ir::System> system =
        load_model(std::filesystem::path(SMCBIP_SOURCE_DIR) / "models" / c.file, c.root);
    ASSERT_TRUE(system) << c.file;
    SCOPED_TRACE(c.file);
    check(*system);
    if (::testing::Test::HasFailure()) return;
  }
}

template <class Engine>
class ExecutionTest : public ::testing::Test {
 protected:
  static engines::SimulateOptions options(std::uint64_t seed) {
    return options_of(Engine::kind, seed);
  }
};

using Engines = ::testing::Types<Reference, Optimised, Multithread>;
TYPED_TEST_SUITE(ExecutionTest, Engines, EngineNames);

TYPED_TEST(ExecutionTest, SteppedRunsAreSimulatorRuns) {
  for_each_model([](const bipc::ir::System& system) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      const engines::SimulateOptions options = TestFixture::options(seed);
      std::ostringstream out;
      Execution execution(system, options, test_externs(), out);
      ASSERT_EQ(execution.problem(), "");
      const Recording stepped = stepped_run(execution);
      expect_same_run(stepped, simulator_run(engines::InterpretedModel(system), options));
      EXPECT_EQ(execution.steps() + 1, stepped.steps.size());
    }
  });
}

/// Conformance models, interpreted and as generated C++.
template <class Engine>
class ExecutionConformance : public ConformanceFixture<Engine> {};

using ConformanceVariants =
    ::testing::Types<Reference, Optimised, GeneratedReference, GeneratedOptimised>;
TYPED_TEST_SUITE(ExecutionConformance, ConformanceVariants, EngineNames);

TYPED_TEST(ExecutionConformance, SteppedRunsAreSimulatorRuns) {
  const std::pair<const char*, const char*> cases[] = {
      {"running/external", "Compound()"},  // extern ports with registered sources
      {"running/writers_buffer", "Compound()"},
      {"running/timed_tempcontrol", "Top()"},
      {"running/test_resume4", "Compound()"},
      {"running/broadcast_up_down", "MyCompoundType()"},
      {"running/priority_rules_atom_closure", "MyCompoundType()"},
      {"running/maximal_progress_hierarchy", "System()"},
      {"running/invariants2", "CT()"},  // ends with an invariant violation
  };
  for (const auto& [model, root] : cases) {
    const std::optional<bipc::ir::System> system = load_conformance_model(model, root);
    ASSERT_TRUE(system);
    std::optional<engines::CompiledModel> compiled;
    if (TypeParam::generated) {
      const engines::CompiledModel::CodeFactory factory = find_generated_conformance(model, root);
      ASSERT_NE(factory, nullptr) << model << " was not generated";
      compiled.emplace(*system, factory);
    }
    const engines::InterpretedModel interpreted(*system);
    const engines::Model& run_model =
        compiled ? static_cast<const engines::Model&>(*compiled) : interpreted;
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      SCOPED_TRACE(std::string(model) + " seed " + std::to_string(seed));
      engines::SimulateOptions options = options_of(TypeParam::kind, seed);
      options.limit = 5000;
      std::ostringstream out;
      Execution execution(run_model, options, test_externs(), out);
      expect_same_run(stepped_run(execution), simulator_run(run_model, options));
      if (this->HasFailure()) return;
    }
  }
}

TYPED_TEST(ExecutionTest, RunUntilSlicesMakeTheSameSteps) {
  for_each_model([](const bipc::ir::System& system) {
    const engines::SimulateOptions options = TestFixture::options(7);
    std::ostringstream out;
    Execution straight(system, options, test_externs(), out);
    const Recording expected = stepped_run(straight);
    // Slices from a third of the run's duration to much less than a step's delay.
    const engines::TimeValue duration = straight.now();
    for (const engines::TimeValue parts : {3, 97, 5000}) {
      const engines::TimeValue slice = std::max<engines::TimeValue>(1, duration / parts);
      SCOPED_TRACE("slice " + std::to_string(slice));
      Execution sliced(system, options, test_externs(), out);
      Recording recording;
      sliced.set_observer(&recording);
      ASSERT_TRUE(sliced.start());
      engines::TimeValue t = 0;
      for (engines::TimeValue calls = 0; calls <= 2 * parts + 2; ++calls) {
        t += slice;
        if (sliced.run_until(t).ended) break;
        // Time passed to t; the next step is due after it.
        ASSERT_EQ(sliced.now(), t);
        const std::optional<engines::TimeValue> next = sliced.next_date();
        ASSERT_TRUE(next && *next > t);
      }
      EXPECT_EQ(recording.steps, expected.steps);
      EXPECT_EQ(recording.end, expected.end);
    }
  });
}

TYPED_TEST(ExecutionTest, AStartedOverRunIsAFreshRun) {
  for_each_model([](const bipc::ir::System& system) {
    const engines::SimulateOptions options = TestFixture::options(3);
    std::ostringstream out;
    Execution execution(system, options, test_externs(), out);
    for (std::uint64_t run = 0; run < 3; ++run) {
      SCOPED_TRACE("run " + std::to_string(run));
      engines::SimulateOptions fresh = options;
      fresh.run_index = run;
      expect_same_run(stepped_run(execution, run),
                      simulator_run(engines::InterpretedModel(system), fresh));
    }
  });
}

// A counter that counts only while `go` is set (nothing in the model sets it), whose count must
// stay below 10 (it would go up to 12).
constexpr const char* kGatedCounter = R"(package gated
  port type Sig()
  connector type Solo(Sig p)
    define p
  end
  atom type Counter()
    data int go, count
    export port Sig tick()
    place S
    initial to S do { go = 0; count = 0; }
    on tick from S to S provided (go == 1 && count < 12) do { count = count + 1; }
    invariant small provided (count < 10)
  end
  compound type Top()
    component Counter c()
    connector Solo run(c.tick)
  end
end
)";

/// A started execution of kGatedCounter and its variables.
struct GatedCounter {
  std::optional<bipc::ir::System> system = load_model_text(kGatedCounter, "Top()");
  std::ostringstream out;
  std::optional<Execution> execution;
  Recording recording;
  engines::DataSlot go, count;

  /// False, with a failure added, when the model does not start.
  bool start(const engines::SimulateOptions& options) {
    if (!system) return false;
    execution.emplace(*system, options, test_externs(), out);
    execution->set_observer(&recording);
    const auto found_go = execution->find_data("ROOT.c", "go");
    const auto found_count = execution->find_data("ROOT.c", "count");
    EXPECT_TRUE(found_go && found_count);
    if (!found_go || !found_count || !execution->start()) return false;
    go = *found_go;
    count = *found_count;
    return true;
  }
};

TYPED_TEST(ExecutionTest, AWriteEnablesAnAtom) {
  GatedCounter counter;
  ASSERT_TRUE(counter.start(TestFixture::options(1)));
  Execution& execution = *counter.execution;
  EXPECT_FALSE(execution.find_data("ROOT.c", "nothing"));
  EXPECT_FALSE(execution.find_data("ROOT.d", "go"));
  StepOutcome outcome = execution.step();
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.end, RunEnd::Deadlock);

  ASSERT_TRUE(execution.write(counter.go.atom, counter.go.slot, engines::make_int(1)));
  for (int i = 1; i <= 5; ++i) {
    outcome = execution.step();
    ASSERT_TRUE(outcome.stepped);
    EXPECT_EQ(outcome.info.fired, StepInfo::Fired::Interaction);
    EXPECT_EQ(execution.read(counter.count.atom, counter.count.slot).i, i);
  }
  ASSERT_TRUE(execution.write(counter.go.atom, counter.go.slot, engines::make_int(0)));
  outcome = execution.step();
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.end, RunEnd::Deadlock);
  EXPECT_EQ(execution.steps(), 5u);
  EXPECT_EQ(execution.read(counter.count.atom, counter.count.slot).i, 5);
  EXPECT_EQ(counter.recording.finishes, 2u);  // each deadlock
}

TYPED_TEST(ExecutionTest, AWriteThatViolatesAnInvariantEndsTheRun) {
  GatedCounter counter;
  ASSERT_TRUE(counter.start(TestFixture::options(1)));
  Execution& execution = *counter.execution;
  const engines::DataSlot x = counter.count;
  EXPECT_FALSE(execution.write(x.atom, x.slot, engines::make_int(20)));
  EXPECT_EQ(execution.result().code, engines::kInvariantViolation);
  EXPECT_EQ(execution.result().end, RunEnd::Error);
  EXPECT_EQ(counter.recording.code, engines::kInvariantViolation);
  const StepOutcome outcome = execution.step();
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.code, engines::kInvariantViolation);
  EXPECT_NE(outcome.message.find("invariant small"), std::string_view::npos) << outcome.message;
  EXPECT_FALSE(execution.write(x.atom, x.slot, engines::make_int(0)));  // over for good
}

TYPED_TEST(ExecutionTest, AStepThatViolatesAnInvariantEndsTheRun) {
  GatedCounter counter;
  ASSERT_TRUE(counter.start(TestFixture::options(1)));
  Execution& execution = *counter.execution;
  ASSERT_TRUE(execution.write(counter.go.atom, counter.go.slot, engines::make_int(1)));
  const StepOutcome outcome = execution.run_until(engines::kPlusInfinity);
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.end, RunEnd::Error);
  EXPECT_EQ(outcome.code, engines::kInvariantViolation);
  EXPECT_EQ(counter.recording.code, engines::kInvariantViolation);
  EXPECT_EQ(execution.steps(), 9u);  // the 10th step violates the invariant
}

// An atom that takes events from a port the host feeds (class Host is not registered).
constexpr const char* kFedSensor = R"(package fed
  port type Int(int v)
  atom type Sensor()
    data int v, sum
    extern port Int reading(v) as "Host" remember
    place S
    initial to S do { v = 0; sum = 0; }
    on reading from S to S do { sum = sum + v; }
  end
  compound type Top()
    component Sensor s()
  end
end
)";

TYPED_TEST(ExecutionTest, AFedPortFiresAtTheFedDate) {
  const std::optional<bipc::ir::System> system = load_model_text(kFedSensor, "Top()");
  ASSERT_TRUE(system);
  engines::SimulateOptions options = TestFixture::options(1);
  options.asap = true;  // each event is taken at its date
  std::ostringstream out;
  Execution execution(*system, options, test_externs(), out, /*fed_capacity=*/2);
  ASSERT_EQ(execution.problem(), "");
  const std::optional<engines::AtomPort> reading = execution.find_port("ROOT.s", "reading");
  const std::optional<engines::DataSlot> sum = execution.find_data("ROOT.s", "sum");
  ASSERT_TRUE(reading && sum);
  ASSERT_TRUE(execution.start());
  EXPECT_EQ(execution.step().end, RunEnd::Deadlock);  // nothing fed yet

  const engines::Val seven[] = {engines::make_int(7)};
  const engines::Val five[] = {engines::make_int(5)};
  EXPECT_FALSE(execution.feed(reading->atom, reading->port, 5'000'000, {}));  // no value
  EXPECT_FALSE(execution.feed(reading->atom, bipc::ir::kNone, 5'000'000, seven));
  EXPECT_TRUE(execution.feed(reading->atom, reading->port, 5'000'000, seven));
  EXPECT_TRUE(execution.feed(reading->atom, reading->port, 8'000'000, five));
  EXPECT_FALSE(execution.feed(reading->atom, reading->port, 9'000'000, five));  // full

  // Nothing is due before 5 ms: time passes to 4 ms.
  StepOutcome outcome = execution.run_until(4'000'000);
  EXPECT_FALSE(outcome.stepped);
  EXPECT_FALSE(outcome.ended);
  EXPECT_EQ(execution.now(), 4'000'000);
  EXPECT_EQ(execution.next_date(), std::optional<engines::TimeValue>(5'000'000));

  outcome = execution.run_until(6'000'000);
  ASSERT_TRUE(outcome.stepped);
  EXPECT_EQ(outcome.info.fired, StepInfo::Fired::External);
  EXPECT_EQ(outcome.info.atom, reading->atom);
  EXPECT_EQ(outcome.info.port, reading->port);
  EXPECT_EQ(outcome.info.time, 5'000'000);
  EXPECT_EQ(execution.read(sum->atom, sum->slot).i, 7);
  // The queue has room again.
  EXPECT_TRUE(execution.feed(reading->atom, reading->port, 20'000'000, five));

  outcome = execution.run_until(30'000'000);
  EXPECT_TRUE(outcome.stepped);
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.end, RunEnd::Deadlock);
  EXPECT_EQ(outcome.info.time, 20'000'000);
  EXPECT_EQ(execution.steps(), 3u);
  EXPECT_EQ(execution.read(sum->atom, sum->slot).i, 17);

  // Fed again after the deadlock: the run goes on.
  EXPECT_TRUE(execution.feed(reading->atom, reading->port, 40'000'000, seven));
  outcome = execution.step();
  ASSERT_TRUE(outcome.stepped);
  EXPECT_EQ(outcome.info.time, 40'000'000);
  EXPECT_EQ(execution.read(sum->atom, sum->slot).i, 24);
}

TEST(Execution, RefusesRealTimeAndReportsItsProblem) {
  const std::optional<bipc::ir::System> system = load_model_text(kGatedCounter, "Top()");
  ASSERT_TRUE(system);
  engines::SimulateOptions options = options_of(engines::EngineKind::Reference, 1);
  options.real_time = true;
  std::ostringstream out;
  Execution execution(*system, options, test_externs(), out);
  EXPECT_NE(execution.problem(), "");
  EXPECT_FALSE(execution.start());
  EXPECT_EQ(execution.result().code, engines::kInputError);
  const StepOutcome outcome = execution.step();
  EXPECT_TRUE(outcome.ended);
  EXPECT_EQ(outcome.code, engines::kInputError);
}

}  // namespace
}  // namespace smcbip::tests
