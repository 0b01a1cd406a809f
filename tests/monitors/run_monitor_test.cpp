// The online monitor on the engines' runs (names resolved against the model) against the same
// runs recorded as JSON-lines traces and judged by check_trace (names bound to the trace):
// the two readings of a state must give the same verdicts.
#include "monitors/run/run_monitor.h"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

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

}  // namespace
}  // namespace smcbip::monitors
