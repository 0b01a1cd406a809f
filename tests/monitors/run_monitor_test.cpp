// The online monitor on the engines' runs (names resolved against the model) against the same
// runs recorded as JSON-lines traces and judged by check_trace (names bound to the trace):
// the two readings of a state must give the same verdicts.
#include "monitors/run/run_monitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "channel_model.h"
#include "engines/engines.h"
#include "monitors/monitors.h"
#include "tests/engines/temp_model.h"

namespace smcbip::monitors {
namespace {

// The Channel model counts milliseconds; the engines, nanoseconds.
constexpr TimeScale kMilliseconds{1e6, 1e9};

constexpr const char* kQueries =
    "P=? [ F[0,100] Channel.lost > 0 ]\n"
    "P=? [ G[0,60] !Receiver.c2 || F[0,30] Sender.acked >= 2 ]\n"
    "P=? [ F[0,200] (fired(loss) && X Sender.READY) ]\n"
    "P=? [ !Channel.delivered U[0,40] Channel.x >= 3 ]\n"
    "P=? [ G (Channel.id_channel <= Sender.seq) ]\n"
    "Pr[<=50](F fired(Receiver.process))\n"
    "P=? [ F{30} Sender.acked == 3 ]\n";

TEST(RunMonitor, AgreesWithTheRecordedTraces) {
  ParsedProperties parsed = parse_properties(kQueries, "channel.mtl");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  resolve_names(parsed.file, channel(), parsed.diagnostics);
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);

  engines::SimulateOptions options;
  options.engine = engines::EngineKind::Optimised;
  options.seed = 2026;
  options.limit = 300;
  options.trace = engines::TraceFormat::Jsonl;
  engines::Simulator recorder(channel(), options, engines::Externs::with_builtins());
  options.silent = true;
  engines::Simulator simulator(channel(), options, engines::Externs::with_builtins());

  std::vector<RunMonitor> monitors;
  for (const Query& q : parsed.file.queries)
    monitors.emplace_back(*q.formula, kMilliseconds, Bindings{}, q.run);
  int trues = 0, falses = 0, undecided = 0;
  for (std::uint64_t run = 0; run < 40; ++run) {
    std::ostringstream trace, sink;
    recorder.run(run, engines::RunStreams{trace, sink});
    std::istringstream recorded(trace.str());
    bipc::Diagnostics diagnostics;
    const TraceReport report =
        check_trace(parsed.file, recorded, "run.jsonl", kMilliseconds, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << diagnostics.format(parsed.sources);
    ASSERT_EQ(report.results.size(), monitors.size());
    for (std::size_t k = 0; k < monitors.size(); ++k) {
      monitors[k].reset();
      std::ostringstream silent;
      simulator.run(run, engines::RunStreams{silent, sink}, &monitors[k]);
      EXPECT_EQ(monitors[k].verdict(), report.results[k].verdict)
          << "run " << run << ": " << to_string(parsed.file.queries[k]);
      const Verdict v = monitors[k].verdict();
      (v == Verdict::True ? trues : v == Verdict::False ? falses : undecided) += 1;
    }
  }
  // The queries and runs are varied enough to decide both ways.
  EXPECT_GT(trues, 20);
  EXPECT_GT(falses, 20);
}

/// Passes a run to a monitor and counts the steps it read before it stopped the run.
class Counting final : public engines::RunObserver {
 public:
  explicit Counting(RunMonitor& monitor) : monitor_(monitor) {}
  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    ++steps;
    return monitor_.observe(step, state);
  }
  void finish(engines::RunEnd end, int code, const std::string& message) override {
    monitor_.finish(end, code, message);
  }
  int steps = 0;

 private:
  RunMonitor& monitor_;
};

/// RunMonitor with its fast monitor against RunMonitor with OnlineMonitor on `runs` runs of
/// `system` for each query (which the fast monitor must take): the runs must stop at the same
/// step with the same verdict and first hit. Returns the verdicts' counts (true, false).
std::pair<int, int> compare_fast_and_general(const bipc::ir::System& system, const char* queries,
                                             engines::SimulateOptions options, int runs) {
  ParsedProperties parsed = parse_properties(queries, "fast.mtl");
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  resolve_names(parsed.file, system, parsed.diagnostics);
  EXPECT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  options.silent = true;
  engines::Simulator simulator(system, options, engines::Externs::with_builtins());
  int trues = 0, falses = 0;
  for (const Query& q : parsed.file.queries) {
    RunMonitor fast(*q.formula, kMilliseconds, {{"k", 2}}, q.run);
    RunMonitor general(*q.formula, kMilliseconds, {{"k", 2}}, q.run, Monitoring::General);
    EXPECT_TRUE(fast.fast()) << to_string(q);
    EXPECT_FALSE(general.fast());
    EXPECT_EQ(fast.decided_by_absorbing(), general.decided_by_absorbing());
    for (int run = 0; run < runs; ++run) {
      std::ostringstream out, err;
      fast.reset();
      general.reset();
      Counting fast_steps(fast), general_steps(general);
      simulator.run(static_cast<std::uint64_t>(run), engines::RunStreams{out, err}, &fast_steps);
      simulator.run(static_cast<std::uint64_t>(run), engines::RunStreams{out, err}, &general_steps);
      EXPECT_EQ(fast.verdict(), general.verdict()) << "run " << run << ": " << to_string(q);
      EXPECT_EQ(fast_steps.steps, general_steps.steps) << "run " << run << ": " << to_string(q);
      const double a = fast.first_hit_ms(), b = general.first_hit_ms();
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b)))
          << "run " << run << ": " << to_string(q) << ": " << a << " against " << b;
      trues += fast.verdict() == Verdict::True;
      falses += fast.verdict() == Verdict::False;
    }
  }
  return {trues, falses};
}

TEST(RunMonitor, FastAndGeneralMonitorsAgreeOnTheChannel) {
  // Runs cut at 120 steps now and then, a time and a step run bound.
  engines::SimulateOptions options;
  options.engine = engines::EngineKind::Optimised;
  options.seed = 11;
  options.limit = 120;
  const auto [trues, falses] =
      compare_fast_and_general(channel(),
                               "const k = 2\n"
                               "P=? [ F[0,100] Channel.lost > 0 ]\n"
                               "P=? [ G (Channel.id_channel <= Sender.seq) ]\n"
                               "P=? [ !Receiver.c2 U[0,40] Sender.acked >= 1 ]\n"
                               "Pr[<=50](F Sender.acked >= k)\n"
                               "P=? [ G[5,60] !(Channel.busy && Receiver.c1) ]\n"
                               "Pr[#<=20](Sender.READY R[0,30] Channel.lost == 0)\n"
                               "P=? [ !F[0,30] (Receiver.c2 || Receiver.received % 2 == 1) ]\n",
                               options, 60);
  EXPECT_GT(trues, 60);
  EXPECT_GT(falses, 60);
}

TEST(RunMonitor, FastAndGeneralMonitorsAgreeOnAbsorbingRuns) {
  // Knuth and Yao's die ends in absorbing states (s == 7), which end the runs here.
  const std::optional<bipc::ir::System> die =
      tests::load_model(std::string(SMCBIP_SOURCE_DIR) + "/models/knuth_yao.bip", "System()");
  ASSERT_TRUE(die);
  engines::SimulateOptions options;
  options.seed = 5;
  options.stop_absorbing = true;
  const auto [trues, falses] = compare_fast_and_general(*die,
                                                        "const k = 2\n"
                                                        "P=? [ F (die.s == 7 && die.d == k) ]\n"
                                                        "P=? [ G (die.s != 7 || die.d != 3) ]\n"
                                                        "P=? [ die.s < 7 U die.d == 2 ]\n"
                                                        "P=? [ !(die.d == 0 R die.s != 7) ]\n",
                                                        options, 200);
  EXPECT_GT(trues, 100);
  EXPECT_GT(falses, 100);
}

TEST(RunMonitor, OtherFormulasFallBackToTheOnlineMonitor) {
  ParsedProperties parsed = parse_properties(
      "P=? [ F[0,200] (fired(loss) && X Sender.READY) ]\n"
      "P=? [ !Channel.delivered U[0,40] Channel.x >= 3 ]\n"
      "P=? [ F{30} Sender.acked == 3 ]\n"
      "P=? [ G[0,60] !Receiver.c2 || F[0,30] Sender.acked >= 2 ]\n"
      "P=? [ F (Sender.acked >= 2 && F[0,5] Receiver.c2) ]\n"
      "P=? [ F[0,10] time > 3 ]\n",
      "other.mtl");
  resolve_names(parsed.file, channel(), parsed.diagnostics);
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.format(parsed.sources);
  for (const Query& q : parsed.file.queries) {
    EXPECT_FALSE(RunMonitor(*q.formula, kMilliseconds, {}, q.run).fast()) << to_string(q);
  }
}

}  // namespace
}  // namespace smcbip::monitors
