// The timing wrappers of TASTE interfaces, run by the engines: a cyclic interface starts at its
// offset and then every period; a sporadic one queues calls up to its queue size, drops the
// others, and starts at most once per MIAT, with the calls' data in order.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "taste2bip/writer/wrappers.h"
#include "tests/engines/temp_model.h"

namespace smcbip::taste2bip {
namespace {

constexpr engines::TimeValue kMs = 1'000'000;  // engine time is in nanoseconds

/// The dates (ms) of each connector's interactions, and the last state's data by atom path and
/// data name.
class Recorder final : public engines::RunObserver {
 public:
  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    const bipc::ir::System& system = state.system();
    if (step.fired == engines::StepInfo::Fired::Interaction) {
      dates[system.connectors[step.connector].path].push_back(static_cast<double>(step.time) /
                                                              static_cast<double>(kMs));
    }
    data.clear();
    for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
      const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
      for (bipc::ir::Index slot = 0; slot < type.data.size(); ++slot) {
        if (type.data[slot].type.kind != bipc::ir::ValueKind::Int) continue;
        data[system.atoms[a].path + "." + type.data[slot].name] = state.data(a, slot).i;
      }
    }
    return true;
  }
  std::map<std::string, std::vector<double>> dates;
  std::map<std::string, std::int64_t> data;
};

Recorder run(const std::string& package, const std::string& root, std::uint64_t steps) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(package, root);
  Recorder recorder;
  if (!system) return recorder;
  engines::SimulateOptions options;
  options.seed = 1;
  options.limit = steps;
  engines::Simulator simulator(*system, options, engines::Externs::with_builtins());
  std::ostringstream trace;
  const engines::RunResult result = simulator.run(0, engines::RunStreams{trace, trace}, &recorder);
  EXPECT_EQ(result.code, engines::kRunOk) << result.message << "\n" << trace.str();
  return recorder;
}

TEST(TimingWrappers, CyclicStartsAtItsOffsetThenEveryPeriod) {
  const std::string package = "package cyclic\n" + port_type("Call", {}) +
                              "  connector type Sync(Call a, Call b)\n    define a b\n  end\n" +
                              cyclic_wrapper("Call") + R"(
  atom type Worker()
    export port Call start(), done()
    place idle, busy
    initial to idle
    on start from idle to busy
    on done from busy to idle
  end
  compound type Top()
    component TASTE_Cyclic w(100, 10, 30)
    component Worker f()
    connector Sync go(w.start, f.start)
    connector Sync back(w.done, f.done)
  end
end
)";
  const Recorder r = run(package, "Top()", 20);
  ASSERT_EQ(r.dates.count("go"), 1u);
  const std::vector<double> expected = {30, 130, 230, 330, 430, 530, 630, 730, 830, 930};
  EXPECT_EQ(r.dates.at("go"), expected);
  EXPECT_EQ(r.dates.at("back"), expected);  // done at once: the function takes no time
}

/// A caller that calls with 0, 1, ..., calls - 1 at 0, 1, ... ms, a sporadic interface with
/// a FIFO of `queue` calls and a MIAT of 50 ms, and a function that folds the data it gets into
/// `sum` (sum * 10 + v + 1, so the order shows) and takes `work` ms.
std::string sporadic_design(int calls, std::uint32_t queue, int work) {
  const std::vector<BipParameter> value = {{"v", "int"}};
  const std::string wrapper = "TASTE_Sporadic_V_" + std::to_string(queue);
  return "package sporadic\n" + port_type("Call", {}) + port_type("CallV", value) +
         "  connector type Pass(CallV s, CallV r)\n    define s r\n    on s r down { r.v = s.v; }\n"
         "  end\n  connector type Sync(Call a, Call b)\n    define a b\n  end\n" +
         sporadic_wrapper(wrapper, "CallV", "Call", value, queue) +
         "  atom type Caller()\n    clock t unit millisecond\n    data int v = 0\n"
         "    export port CallV call(v)\n    place calling\n    initial to calling do { t = 0; }\n"
         "    on call from calling to calling provided (v < " +
         std::to_string(calls) +
         " && t >= v) eager do { v = v + 1; }\n  end\n"
         "  atom type Worker()\n    clock t unit millisecond\n    data int v = 0\n"
         "    data int sum = 0\n    export port CallV start(v)\n    export port Call done()\n"
         "    place idle, busy\n    initial to idle\n"
         "    on start from idle to busy do { sum = sum * 10 + v + 1; t = 0; }\n"
         "    on done from busy to idle provided (t >= " +
         std::to_string(work) +
         ")\n  end\n"
         "  compound type Top()\n    component Caller c()\n    component " +
         wrapper +
         " w(50, 10)\n    component Worker f()\n    connector Pass send(c.call, w.call)\n"
         "    connector Pass go(w.start, f.start)\n    connector Sync back(w.done, f.done)\n"
         "  end\nend\n";
}

TEST(TimingWrappers, SporadicQueuesDropsAndKeepsItsMiat) {
  const Recorder r = run(sporadic_design(3, 1, 0), "Top()", 30);
  EXPECT_EQ(r.dates.at("send"), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(r.dates.at("go"), (std::vector<double>{0, 50}));  // the second waits for the MIAT
  EXPECT_EQ(r.data.at("w.dropped"), 1);                       // the third found the FIFO full
  EXPECT_EQ(r.data.at("f.sum"), 12);  // the calls with 0, then 1: their data, in order
}

TEST(TimingWrappers, ALongerFifoKeepsItsCallsInOrder) {
  const Recorder r = run(sporadic_design(5, 3, 0), "Top()", 40);
  // At 0 the first call starts at once; the next three wait in the FIFO, the fifth is dropped.
  EXPECT_EQ(r.dates.at("go"), (std::vector<double>{0, 50, 100, 150}));
  EXPECT_EQ(r.data.at("w.dropped"), 1);
  EXPECT_EQ(r.data.at("f.sum"), 1234);
}

TEST(TimingWrappers, AMissedDeadlineStopsTime) {
  // The function takes 20 ms against a deadline of 10 ms: time cannot pass 10 ms after its start.
  const std::optional<bipc::ir::System> system =
      tests::load_model_text(sporadic_design(1, 1, 20), "Top()");
  ASSERT_TRUE(system);
  engines::SimulateOptions options;
  options.seed = 1;
  options.limit = 30;
  engines::Simulator simulator(*system, options, engines::Externs::with_builtins());
  std::ostringstream trace;
  const engines::RunResult result = simulator.run(0, engines::RunStreams{trace, trace});
  EXPECT_EQ(result.end, engines::RunEnd::Timelock) << trace.str();
}

}  // namespace
}  // namespace smcbip::taste2bip
