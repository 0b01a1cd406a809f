// The stochastic engine (race of planned dates): firing dates of @stochastic ports fit their
// distributions, also truncated at an advanced clock; races between ports follow their rates;
// runs are reproducible from (seed, run index); the JSON-lines trace is well formed.
//
// Goodness of fit: one-sample Kolmogorov-Smirnov tests over 10,000 firing dates (one per run,
// run indices 0..9999 of a fixed seed) at significance 0.001 (see kolmogorov.h). Frequencies:
// a Bernoulli proportion over N trials is compared with its theoretical value within 3
// standard errors sqrt(p(1-p)/N) (a false alarm has probability 0.27% for a fixed seed).
#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bipc/bipc.h"
#include "engines/engines.h"
#include "kolmogorov.h"
#include "temp_model.h"

namespace smcbip::engines {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kRuns = 10000;
constexpr std::uint64_t kSeed = 20261121;

using tests::TempDir;

bipc::ir::System load(const fs::path& file, const std::string& root) {
  std::optional<bipc::ir::System> system = tests::load_model(file, root);
  return system ? std::move(*system) : bipc::ir::System{};
}

/// One atom whose port `fire` draws from `dist(params)` on clock x, after an eager internal
/// step at x == wait (ms) that advances the clock without resetting it.
std::string single_port_model(const std::string& dist, const std::string& params, int wait) {
  return R"(package single
  port type P()
  connector type Solo(P p)
    define p
  end
  atom type A()
    clock x unit millisecond
    @stochastic(dist=")" +
         dist + R"(", clk=x, param=")" + params + R"(")
    export port P fire()
    port P wait()
    place S0, S1, S2
    initial to S0 do { x = 0; }
    on wait from S0 to S1 provided (x == )" +
         std::to_string(wait) + R"() eager
    on fire from S1 to S2
  end
  compound type Top()
    component A a()
    connector Solo c(a.fire)
  end
end
)";
}

/// Records the date (ms) of the first interaction of a run.
class FirstInteraction : public RunObserver {
 public:
  bool observe(const StepInfo& step, const StateView& /*state*/) override {
    if (step.fired != StepInfo::Fired::Interaction) return true;
    date_ms = static_cast<double>(step.time) / 1e6;
    return false;
  }
  double date_ms = -1.0;
};

std::vector<double> firing_dates(const bipc::ir::System& system) {
  SimulateOptions options;
  options.seed = kSeed;
  options.silent = true;
  const Externs externs = Externs::with_builtins();
  Simulator simulator(system, options, externs);
  EXPECT_TRUE(simulator.stochastic());
  std::ostringstream sink;
  std::vector<double> dates;
  for (std::uint64_t run = 0; run < kRuns; ++run) {
    FirstInteraction first;
    const RunResult result = simulator.run(run, RunStreams{sink, sink}, &first);
    EXPECT_EQ(result.code, kRunOk) << result.message;
    if (first.date_ms < 0) {
      ADD_FAILURE() << "run " << run << " fired no interaction";
      break;
    }
    dates.push_back(first.date_ms);
  }
  return dates;
}

struct DateCase {
  std::string name, dist, params;
  std::function<double(double)> cdf;
  int truncate_at;  // ms the clock has advanced when the port becomes enabled
};

std::vector<DateCase> date_cases() {
  return {
      {"normal", "normal", "10,2", [](double x) { return gsl_cdf_gaussian_P(x - 10, 2); }, 0},
      {"exponential", "exponential", "3", [](double x) { return gsl_cdf_exponential_P(x, 3); }, 0},
      {"gamma", "gamma", "2.5,1.5", [](double x) { return gsl_cdf_gamma_P(x, 2.5, 1.5); }, 0},
      {"chi2", "chi2", "3", [](double x) { return gsl_cdf_chisq_P(x, 3); }, 0},
      {"uniform", "uniform", "2,7", [](double x) { return gsl_cdf_flat_P(x, 2, 7); }, 0},
      {"lognormal", "lognormal", "1,0.5", [](double x) { return gsl_cdf_lognormal_P(x, 1, 0.5); },
       0},
      {"weibull", "weibull", "2,1.5", [](double x) { return gsl_cdf_weibull_P(x, 2, 1.5); }, 0},
      {"normal_truncated", "normal", "10,2", [](double x) { return gsl_cdf_gaussian_P(x - 10, 2); },
       11},
      {"exponential_truncated", "exponential", "3",
       [](double x) { return gsl_cdf_exponential_P(x, 3); }, 2},
      {"gamma_truncated", "gamma", "2.5,1.5", [](double x) { return gsl_cdf_gamma_P(x, 2.5, 1.5); },
       3},
      {"uniform_truncated", "uniform", "2,7", [](double x) { return gsl_cdf_flat_P(x, 2, 7); }, 4},
      {"weibull_truncated", "weibull", "2,1.5",
       [](double x) { return gsl_cdf_weibull_P(x, 2, 1.5); }, 1},
  };
}

TEST(StochasticEngine, FiringDatesFitTheirDistribution) {
  TempDir dir;
  for (const DateCase& c : date_cases()) {
    SCOPED_TRACE(c.name);
    const fs::path file =
        dir.write(c.name + ".bip", single_port_model(c.dist, c.params, c.truncate_at));
    const bipc::ir::System system = load(file, "Top()");
    const std::vector<double> dates = firing_dates(system);
    ASSERT_EQ(dates.size(), kRuns);
    // Truncated at the clock's value T: P(X <= x | X > T) = (F(x) - F(T)) / (1 - F(T)).
    const double at = c.truncate_at;
    const double below = at > 0 ? c.cdf(at) : 0.0;
    auto conditional = [&](double x) { return (c.cdf(x) - below) / (1.0 - below); };
    for (double d : dates) ASSERT_GT(d, at);
    EXPECT_LT(tests::kolmogorov_statistic(dates, conditional), tests::kolmogorov_critical());
  }
}

TEST(StochasticEngine, CustomDistributionFromAFile) {
  TempDir dir;
  dir.write("delays.cdf", "# value cdf\n1 0\n2 0.25\n4 0.75\n8 1\n");
  const fs::path file = dir.write("custom.bip", single_port_model("custom", "delays.cdf", 0));
  const std::vector<double> dates = firing_dates(load(file, "Top()"));
  auto cdf = [](double x) {
    if (x <= 1) return 0.0;
    if (x <= 2) return 0.25 * (x - 1);
    if (x <= 4) return 0.25 + 0.25 * (x - 2);
    if (x <= 8) return 0.75 + 0.0625 * (x - 4);
    return 1.0;
  };
  EXPECT_LT(tests::kolmogorov_statistic(dates, cdf), tests::kolmogorov_critical());
}

TEST(StochasticEngine, MissedSupportIsAModelError) {
  TempDir dir;
  // uniform(0, 5) once the clock is at 6: no date of the distribution lies ahead.
  const fs::path file = dir.write("missed.bip", single_port_model("uniform", "0,5", 6));
  const bipc::ir::System system = load(file, "Top()");
  SimulateOptions options;
  options.seed = 1;
  std::ostringstream out;
  const RunResult result = simulate(system, options, Externs::with_builtins(), out);
  EXPECT_EQ(result.code, kInputError);
  EXPECT_NE(result.message.find("missed support: ROOT.a.fire"), std::string::npos)
      << result.message;
  EXPECT_NE(out.str().find("[BIP ENGINE]: ERROR: missed support"), std::string::npos) << out.str();
}

/// Records the date (ms) of every interaction of a run.
class InteractionDates : public RunObserver {
 public:
  bool observe(const StepInfo& step, const StateView& /*state*/) override {
    if (step.fired == StepInfo::Fired::Interaction) {
      dates_ms.push_back(static_cast<double>(step.time) / 1e6);
    }
    return true;
  }
  std::vector<double> dates_ms;
};

// One port drawn from again and again in a run, truncated at 1 ms and at 3 ms in turn: each
// draw uses its own truncation's mass below, which the planner keeps only for the last
// truncation point. Exponential(3): conditioned on X > T, F(x) = (F(x) - F(T)) / (1 - F(T)).
TEST(StochasticEngine, RepeatedDrawsKeepEachTruncationsMass) {
  TempDir dir;
  const fs::path file = dir.write("alternate.bip", R"(package alternate
  port type P()
  connector type Solo(P p)
    define p
  end
  atom type A()
    clock x unit millisecond
    @stochastic(dist="exponential", clk=x, param="3")
    export port P fire()
    port P wait()
    place W1, F1, W3, F3
    initial to W1 do { x = 0; }
    on wait from W1 to F1 provided (x == 1) eager
    on fire from F1 to W3 do { x = 0; }
    on wait from W3 to F3 provided (x == 3) eager
    on fire from F3 to W1 do { x = 0; }
  end
  compound type Top()
    component A a()
    connector Solo c(a.fire)
  end
end
)");
  const bipc::ir::System system = load(file, "Top()");
  SimulateOptions options;
  options.seed = kSeed;
  options.silent = true;
  options.limit = 4 * 5000;  // two internal steps and two draws per round
  const Externs externs = Externs::with_builtins();
  Simulator simulator(system, options, externs);
  std::ostringstream sink;
  InteractionDates observed;
  const RunResult result = simulator.run(0, RunStreams{sink, sink}, &observed);
  ASSERT_EQ(result.code, kRunOk) << result.message;
  ASSERT_EQ(observed.dates_ms.size(), 2 * 5000u);
  std::vector<double> after_1, after_3;  // the clock's value at each firing: the sample
  double reset = 0.0;
  for (std::size_t i = 0; i < observed.dates_ms.size(); ++i) {
    (i % 2 == 0 ? after_1 : after_3).push_back(observed.dates_ms[i] - reset);
    reset = observed.dates_ms[i];
  }
  for (const auto& [truncation, samples] : {std::pair{1.0, &after_1}, std::pair{3.0, &after_3}}) {
    SCOPED_TRACE(truncation);
    const double below = gsl_cdf_exponential_P(truncation, 3);
    auto conditional = [&](double x) {
      return (gsl_cdf_exponential_P(x, 3) - below) / (1.0 - below);
    };
    for (double d : *samples) ASSERT_GT(d, truncation);
    EXPECT_LT(tests::kolmogorov_statistic(*samples, conditional), tests::kolmogorov_critical());
  }
}

fs::path source_model(const std::string& name) {
  return fs::path(SMCBIP_SOURCE_DIR) / "models" / name;
}

/// The value of data `name` of atom `path` in the state an observer sees last.
class FinalData : public RunObserver {
 public:
  FinalData(const bipc::ir::System& system, const std::string& path, const std::string& name) {
    for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
      if (system.atoms[a].path != path) continue;
      atom_ = a;
      const auto& data = system.atom_types[system.atoms[a].type].data;
      for (bipc::ir::Index d = 0; d < data.size(); ++d) {
        if (data[d].name == name) slot_ = d;
      }
    }
  }
  bool observe(const StepInfo& /*step*/, const StateView& state) override {
    value = state.data(atom_, slot_).i;
    return true;
  }
  std::int64_t value = -1;

 private:
  bipc::ir::Index atom_ = 0, slot_ = 0;
};

TEST(StochasticEngine, RaceOfTwoExponentialsFollowsTheRates) {
  const bipc::ir::System system = load(source_model("two_exponentials.bip"), "System()");
  SimulateOptions options;
  options.seed = kSeed;
  options.silent = true;
  const Externs externs = Externs::with_builtins();
  Simulator simulator(system, options, externs);
  std::ostringstream sink;
  std::size_t a_wins = 0;
  for (std::uint64_t run = 0; run < kRuns; ++run) {
    FinalData winner(system, "judge", "winner");
    simulator.run(run, RunStreams{sink, sink}, &winner);
    ASSERT_TRUE(winner.value == 1 || winner.value == 2) << "run " << run;
    a_wins += winner.value == 1;
  }
  // Rates 1/10 and 1/20: P(a first) = (1/10) / (1/10 + 1/20) = 2/3.
  const double p = 2.0 / 3.0;
  const double se = std::sqrt(p * (1 - p) / kRuns);
  EXPECT_NEAR(static_cast<double>(a_wins) / kRuns, p, 3 * se);
}

/// Counts the interactions of two connectors over a run.
class ConnectorCounts : public RunObserver {
 public:
  ConnectorCounts(const bipc::ir::System& system, const std::string& a, const std::string& b) {
    for (bipc::ir::Index k = 0; k < system.connectors.size(); ++k) {
      if (system.connectors[k].path == a) a_ = k;
      if (system.connectors[k].path == b) b_ = k;
    }
  }
  bool observe(const StepInfo& step, const StateView& /*state*/) override {
    if (step.fired == StepInfo::Fired::Interaction) {
      count_a += step.connector == a_;
      count_b += step.connector == b_;
    }
    return true;
  }
  std::size_t count_a = 0, count_b = 0;

 private:
  bipc::ir::Index a_ = bipc::ir::kNone, b_ = bipc::ir::kNone;
};

TEST(StochasticEngine, ChannelLosesAcknowledgementsAtTheNormalTailRate) {
  const bipc::ir::System system = load(source_model("channel.bip"), "System()");
  SimulateOptions options;
  options.seed = kSeed;
  options.silent = true;
  options.limit = 400;
  const Externs externs = Externs::with_builtins();
  Simulator simulator(system, options, externs);
  ASSERT_TRUE(simulator.stochastic());
  std::ostringstream sink;
  ConnectorCounts counts(system, "loss", "ack_back");
  for (std::uint64_t run = 0; run < 300; ++run) {
    const RunResult result = simulator.run(run, RunStreams{sink, sink}, &counts);
    ASSERT_EQ(result.code, kRunOk) << result.message;
  }
  // Every attempt draws a fresh normal(10, 2) delay; the eager timeout at 13 ms wins when the
  // delay exceeds it: p = 1 - Phi(1.5).
  const double trials = static_cast<double>(counts.count_a + counts.count_b);
  ASSERT_GT(trials, 10000.0);
  const double p = gsl_cdf_ugaussian_Q(1.5);
  const double se = std::sqrt(p * (1 - p) / trials);
  EXPECT_NEAR(static_cast<double>(counts.count_a) / trials, p, 3 * se);
}

std::string jsonl_run(const bipc::ir::System& system, std::uint64_t run_index) {
  SimulateOptions options;
  options.seed = 7;
  options.run_index = run_index;
  options.limit = 30;
  options.trace = TraceFormat::Jsonl;
  std::ostringstream out;
  simulate(system, options, Externs::with_builtins(), out);
  return out.str();
}

TEST(StochasticEngine, RunsAreReproducibleFromSeedAndRunIndex) {
  const bipc::ir::System system = load(source_model("channel.bip"), "System()");
  EXPECT_EQ(jsonl_run(system, 3), jsonl_run(system, 3));
  EXPECT_NE(jsonl_run(system, 3), jsonl_run(system, 4));
}

TEST(JsonlTrace, OneObjectPerStateThenTheEnd) {
  const bipc::ir::System system = load(source_model("channel.bip"), "System()");
  std::istringstream lines(jsonl_run(system, 0));
  std::vector<nlohmann::json> objects;
  for (std::string line; std::getline(lines, line);) objects.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(objects.size(), 33u) << "header, initial state, 30 steps, end";
  // The header names the run and declares the clocks with their units.
  const nlohmann::json& header = objects.front()["header"];
  EXPECT_EQ(header["format"], "smcbip-trace");
  EXPECT_EQ(header["seed"], 7);
  EXPECT_EQ(header["run"], 0);
  EXPECT_EQ(header["clocks"]["ROOT.Channel.x"]["unit_ns"], 1000000);
  objects.erase(objects.begin());
  const nlohmann::json& first = objects.front();
  EXPECT_EQ(first["step"], 0);
  EXPECT_EQ(first["time"], 0.0);
  EXPECT_TRUE(first["fired"].is_null());
  EXPECT_EQ(first["places"]["ROOT.Sender"], nlohmann::json::array({"READY"}));
  EXPECT_EQ(first["data"]["ROOT.Sender.seq"], 1);
  EXPECT_EQ(first["data"]["ROOT.Channel.x"], 0.0);
  double last_time = 0.0;
  for (std::size_t i = 1; i + 1 < objects.size(); ++i) {
    EXPECT_EQ(objects[i]["step"], i);
    EXPECT_TRUE(objects[i]["fired"].is_string());
    EXPECT_GE(objects[i]["time"].get<double>(), last_time);
    last_time = objects[i]["time"].get<double>();
  }
  EXPECT_EQ(objects[1]["fired"], "ROOT.request");
  EXPECT_EQ(objects.back(), nlohmann::json({{"end", "limit"}}));
}

}  // namespace
}  // namespace smcbip::engines
