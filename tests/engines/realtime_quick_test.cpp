// Quick checks of --real-time and --relaxed on small models written here, typed over the engines.
// Every check is one-sided or bounded by seconds, so that a loaded machine cannot fail it: the
// engine sleeps until each planned date, and a deadline is only ever missed on purpose, by an
// action that sleeps five times longer than the deadline allows. The whole file takes well under
// a second of wall time per engine.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "bipc/bipc.h"
#include "engines/api/externs.h"
#include "engines/api/time_value.h"
#include "engines/engines.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;
using engines::TimeValue;
using std::chrono::milliseconds;

/// Three ticks at least 20 ms apart, lazy so that no deadline can be missed however late the
/// engine wakes up; the run then deadlocks. With --asap the dates are 20, 40 and 60 ms.
constexpr const char* kTicks = R"(package rt_ticks
  port type Port()

  atom type Ticker(int N)
    data int n
    clock x unit millisecond
    port Port tick()
    place L
    initial to L do { n = 0; x = 0; }
    on tick from L to L provided (n < N && x >= 20) do { n = n + 1; x = 0; }
  end

  compound type Top()
    component Ticker T(3)
  end
end
)";
constexpr TimeValue kTickPeriod = 20'000'000;  // ns
constexpr std::size_t kTicksCount = 3;

/// `work` resets x and sleeps 50 ms; then `quick` is eager within x <= 10, a deadline the
/// platform has necessarily passed when the action returns (usleep sleeps at least as long as
/// asked). `done` (x >= 20) is what a relaxed run can still do afterwards.
constexpr const char* kLate = R"(package rt_late
  extern function usleep(int)
  port type Port()

  atom type Worker()
    clock x unit millisecond
    port Port work(), quick(), done()
    place A, B, C
    initial to A do { x = 0; }
    on work from A to B do { x = 0; usleep(50000); }
    on quick from B to C provided (x <= 10) eager
    on done from B to C provided (x >= 20)
  end

  compound type Top()
    component Worker W()
  end
end
)";

/// Parses a time as format_time prints it (`0`, `1s500ms`, `22us742ns`), or nullopt.
std::optional<TimeValue> parse_time(const std::string& text) {
  if (text == "0") return 0;
  static const std::regex part("([0-9]+)(day|hr|min|s|ms|us|ns)");
  TimeValue total = 0;
  std::size_t consumed = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), part); it != std::sregex_iterator();
       ++it) {
    if (static_cast<std::size_t>(it->position()) != consumed) return std::nullopt;
    consumed += static_cast<std::size_t>(it->length());
    const std::string unit = (*it)[2].str();
    const TimeValue scale = unit == "day"   ? 86'400'000'000'000
                            : unit == "hr"  ? 3'600'000'000'000
                            : unit == "min" ? 60'000'000'000
                            : unit == "s"   ? 1'000'000'000
                            : unit == "ms"  ? 1'000'000
                            : unit == "us"  ? 1'000
                                            : 1;
    total += std::stoll((*it)[1].str()) * scale;
  }
  if (consumed == 0 || consumed != text.size()) return std::nullopt;
  return total;
}

TEST(RealTimeQuickParseTime, ReadsWhatFormatTimePrints) {
  for (TimeValue t : {TimeValue{0}, TimeValue{1}, TimeValue{22'742}, TimeValue{1'500'000'000},
                      TimeValue{90'061'000'000'001}}) {
    EXPECT_EQ(parse_time(engines::format_time(t)), t) << engines::format_time(t);
  }
  EXPECT_EQ(parse_time("5x"), std::nullopt);
  EXPECT_EQ(parse_time("ms"), std::nullopt);
}

/// Every date of the trace in order: the state headers' `global time T:` and the choose lines'
/// `at global time T`.
std::vector<TimeValue> trace_dates(const Lines& lines) {
  static const std::regex date("global time ([0-9a-z]+)(:|$)");
  std::vector<TimeValue> dates;
  for (const std::string& line : lines) {
    std::smatch m;
    if (!std::regex_search(line, m, date)) continue;
    const std::optional<TimeValue> t = parse_time(m[1].str());
    EXPECT_TRUE(t.has_value()) << "unreadable date in: " << line;
    if (t) dates.push_back(*t);
  }
  return dates;
}

/// A run and the wall time simulate() took.
struct TimedRun {
  ConformanceRun run;
  std::chrono::steady_clock::duration elapsed{};
};

template <class Engine>
class RealTimeQuick : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("smcbip_realtime_quick_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

  /// --real-time options for this engine, dates at the earliest (--asap).
  static engines::SimulateOptions real_time() {
    engines::SimulateOptions options;
    options.engine = Engine::kind;
    options.real_time = true;
    options.asap = true;
    options.seed = 1;
    return options;
  }

  /// Writes `text` as package `name`, loads it with root `Top()`, runs it once under `options`.
  std::optional<TimedRun> run(const std::string& name, const std::string& text,
                              const engines::SimulateOptions& options) {
    const std::filesystem::path file = dir_ / (name + ".bip");
    {
      std::ofstream out(file);
      out << text;
      if (!out.good()) {
        ADD_FAILURE() << "cannot write " << file;
        return std::nullopt;
      }
    }
    bipc::FrontendResult loaded = bipc::run_frontend({file.string(), {}, "Top()"}, true);
    if (!loaded.system || loaded.diags.has_errors()) {
      ADD_FAILURE() << loaded.diags.format(loaded.model.files);
      return std::nullopt;
    }
    const engines::Externs externs = engines::Externs::with_builtins();
    std::ostringstream out;
    TimedRun result;
    const auto start = std::chrono::steady_clock::now();
    result.run.result = engines::simulate(*loaded.system, options, externs, out);
    result.elapsed = std::chrono::steady_clock::now() - start;
    result.run.text = std::move(out).str();
    result.run.lines = split_lines(result.run.text);
    return result;
  }

  std::filesystem::path dir_;
};
TYPED_TEST_SUITE(RealTimeQuick, AllEngines, EngineNames);

TYPED_TEST(RealTimeQuick, WallTimeCoversTheLastDate) {
  const std::optional<TimedRun> timed = this->run("rt_ticks", kTicks, this->real_time());
  ASSERT_TRUE(timed.has_value());
  const ConformanceRun& run = timed->run;
  EXPECT_EQ(run.result.code, kRunOk) << run.text;
  EXPECT_EQ(state_header(run.lines, kTicksCount), "deadlock!") << run.text;
  const Lines choices = choose_lines(run.lines);
  ASSERT_EQ(choices.size(), kTicksCount) << run.text;
  const std::vector<TimeValue> last = trace_dates(Lines{choices.back()});
  ASSERT_EQ(last.size(), 1u) << choices.back();
  // Each tick waits 20 ms of model time after the previous one.
  EXPECT_GE(last[0], static_cast<TimeValue>(kTicksCount) * kTickPeriod);
  // The engine sleeps until each chosen date before executing it, and its clock starts after
  // our stopwatch: a lower bound that holds on any machine.
  EXPECT_GE(timed->elapsed, std::chrono::nanoseconds(last[0]));
  // Tolerance: 2 s of scheduling delay on top of the model's dates.
  EXPECT_LE(timed->elapsed, std::chrono::nanoseconds(last[0]) + std::chrono::seconds(2));
}

TYPED_TEST(RealTimeQuick, DatesNeverDecrease) {
  const std::optional<TimedRun> timed = this->run("rt_ticks", kTicks, this->real_time());
  ASSERT_TRUE(timed.has_value());
  const std::vector<TimeValue> dates = trace_dates(timed->run.lines);
  // Headers and choices of 3 steps and the final header.
  ASSERT_EQ(dates.size(), 2 * kTicksCount + 1) << timed->run.text;
  for (std::size_t i = 1; i < dates.size(); ++i) {
    EXPECT_LE(dates[i - 1], dates[i]) << "date " << i << " in:\n" << timed->run.text;
  }
}

/// The violation block lines that name the missed `quick` deadline, and none that name `done`.
void expect_quick_named(const ConformanceRun& run) {
  EXPECT_EQ(count(run.lines, "^\\[BIP ENGINE]:   ROOT\\.W\\.quick .* eager$"), 1u) << run.text;
  EXPECT_TRUE(lacks(run.lines, "^\\[BIP ENGINE]:   ROOT\\.W\\.done ")) << run.text;
}

TYPED_TEST(RealTimeQuick, SleepPastAnEagerDeadlineIsATimeSafetyViolation) {
  const std::optional<TimedRun> timed = this->run("rt_late", kLate, this->real_time());
  ASSERT_TRUE(timed.has_value());
  const ConformanceRun& run = timed->run;
  expect_run_error(run, engines::kTimeSafetyViolation);
  EXPECT_TRUE(has(run.lines, "ERROR: .*state #1 .*violation of the following timing constraints"))
      << run.text;
  expect_quick_named(run);
  // The run stops at the violation: only `work` was chosen.
  EXPECT_EQ(choose_lines(run.lines).size(), 1u) << run.text;
}

TYPED_TEST(RealTimeQuick, RelaxedReportsTheViolationAndGoesOn) {
  engines::SimulateOptions options = this->real_time();
  options.relaxed = true;
  const std::optional<TimedRun> timed = this->run("rt_late", kLate, options);
  ASSERT_TRUE(timed.has_value());
  const ConformanceRun& run = timed->run;
  EXPECT_EQ(run.result.code, kRunOk) << run.text;
  EXPECT_TRUE(lacks(run.lines, "ERROR")) << run.text;
  EXPECT_EQ(count(run.lines, "WARNING: .*state #1 .*violation of the following timing constraints"),
            1u)
      << run.text;
  expect_quick_named(run);
  // `quick` can no longer run; `done` (x >= 20, already true) does, then nothing is left.
  EXPECT_TRUE(has(run.lines, "choose .*W\\.done")) << run.text;
  EXPECT_TRUE(lacks(run.lines, "choose .*W\\.quick")) << run.text;
  EXPECT_EQ(state_header(run.lines, 2), "deadlock!") << run.text;
}

}  // namespace
}  // namespace smcbip::tests
