// OperatorMonitor against OnlineMonitor, the general monitor whose verdicts it must give: on
// random formulas of every shape it takes (F, G, U, R, negated, bounded or not, over state
// formulas) and random traces (fixed seeds) with steps and bounds on the same dates, steps
// sharing a date, every way a run ends and every run bound, both must decide at the same
// step, give the same verdict and the same first hits. Then RunMonitor on the engines' runs of
// two models, fast against general, and which formulas fall back to OnlineMonitor.
#include "monitors/online/operator_monitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "channel_model.h"
#include "engines/engines.h"
#include "monitors/monitors.h"

namespace smcbip::monitors {
namespace {

// Dates and bounds in whole ticks, so that bounds fall on the steps' dates exactly.
constexpr TimeScale kTicks{1.0, 1.0};

struct Step {
  online::Tick time = 0;
  std::map<std::string, double> values;  // p, q (0 or 1), x (0 to 4)
};

struct Trace {
  std::vector<Step> steps;  // may be empty
  RunEnd end = RunEnd::Cut;
};

class StepView final : public StateView {
 public:
  explicit StepView(const Step& step) : step_(step) {}
  double value(const Expr& name) const override { return step_.values.at(name.path); }
  bool fired(const Expr&) const override { return false; }

 private:
  const Step& step_;
};

std::string describe(const Trace& trace) {
  static const char* const kEnds[] = {"deadlock", "timelock", "cut", "absorbing"};
  std::string text;
  for (const Step& s : trace.steps) {
    text += "(" + std::to_string(s.time) + ": p=" + std::to_string(int(s.values.at("p"))) +
            " q=" + std::to_string(int(s.values.at("q"))) +
            " x=" + std::to_string(int(s.values.at("x"))) + ") ";
  }
  return text + kEnds[static_cast<int>(trace.end)];
}

class Random {
 public:
  explicit Random(std::uint32_t seed) : random_(seed) {}
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }

  /// A query of a shape OperatorMonitor takes, with a run bound now and then.
  std::string query() {
    static const char* const kStates[] = {"p",
                                          "q",
                                          "!p",
                                          "p && q",
                                          "p || !q",
                                          "p -> q",
                                          "p <-> q",
                                          "true",
                                          "false",
                                          "init",
                                          "x >= 2",
                                          "x == k",
                                          "x % 2 == 0",
                                          "abs(x - 2) < 1",
                                          "min(x, 3) == x && q",
                                          "x / 2 > 1",
                                          "!(p && x > 1)",
                                          "p && q && x != 0 || !p && x == 4",
                                          "x >= 1 && x != 3 && p == 1",
                                          "x == 0 || x == k"};
    auto state = [&] { return std::string("(") + kStates[pick(20)] + ")"; };
    std::string negation = pick(3) == 0 ? "!" : pick(8) == 0 ? "!!" : "";
    std::string formula;
    switch (pick(4)) {
      case 0:
        formula = "F" + bound() + " " + state();
        break;
      case 1:
        formula = "G" + bound() + " " + state();
        break;
      case 2:
        formula = state() + " U" + bound() + " " + state();
        break;
      default:
        formula = state() + " R" + bound() + " " + state();
        break;
    }
    formula = negation + "(" + formula + ")";
    switch (pick(5)) {
      case 0:
        return "Pr[<=" + std::to_string(pick(12)) + "](" + formula + ")";
      case 1:
        return "Pr[#<=" + std::to_string(pick(6)) + "](" + formula + ")";
      default:
        return "P=? [ " + formula + " ]";
    }
  }

  /// Up to 8 steps (none now and then) 0 to 3 ticks apart, and how the run ends.
  Trace trace() {
    Trace trace;
    trace.end = static_cast<RunEnd>(pick(4));
    const int steps = pick(12) == 0 ? 0 : 1 + pick(8);
    online::Tick time = pick(3);  // the run's start need not be 0
    for (int i = 0; i < steps; ++i) {
      if (i > 0) time += pick(4) == 0 ? 0 : 1 + pick(3);
      trace.steps.push_back({time, {{"p", pick(2)}, {"q", pick(2)}, {"x", pick(5)}}});
    }
    return trace;
  }

 private:
  std::string bound() {
    if (pick(4) == 0) return "";
    const int low = pick(3) == 0 ? 0 : pick(6);
    return "[" + std::to_string(low) + "," + std::to_string(low + pick(6)) + "]";
  }

  std::mt19937 random_;
};

/// What a monitor made of a run: the step at which it decided (-1: at the end), and then.
struct Judged {
  int decided_at = -1;
  Verdict verdict = Verdict::Undecided;
  online::Pos sure_hit, possible_hit;
  friend bool operator==(const Judged&, const Judged&) = default;
};

template <class Monitor>
Judged judge(Monitor& monitor, const Trace& trace) {
  Judged judged;
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const Verdict v = monitor.step(StepView(trace.steps[i]), trace.steps[i].time);
    if (v != Verdict::Undecided && judged.decided_at < 0) judged.decided_at = static_cast<int>(i);
  }
  judged.verdict = monitor.end(trace.end);
  judged.sure_hit = monitor.first_hit_for_sure();
  judged.possible_hit = monitor.first_hit_possibly();
  return judged;
}

std::string describe(const Judged& j) {
  static const char* const kVerdicts[] = {"false", "true", "undecided"};
  return std::string(kVerdicts[static_cast<int>(j.verdict)]) + " at step " +
         std::to_string(j.decided_at) + ", hits " + std::to_string(j.sure_hit.t) + "/" +
         std::to_string(j.possible_hit.t);
}

/// The counts of verdicts, decisions before the end and first hits of the cases compared.
struct Tally {
  int cases = 0, trues = 0, falses = 0, undecided = 0, early = 0, hits = 0;
};

/// Compares OperatorMonitor for `query` with OnlineMonitor for `reference_query` on `runs`
/// random traces; returns how many cases differ (the first few are reported when `report`).
int differences(std::uint32_t seed, int cases, int runs, Tally& tally, int report,
                const std::string& (*reference)(const std::string&) = nullptr) {
  Random random(seed);
  int differ = 0;
  for (int c = 0; c < cases; ++c) {
    const std::string text = random.query();
    const std::string reference_text = reference ? reference(text) : text;
    const ParsedProperties parsed = parse_properties(text, "q.mtl");
    const ParsedProperties other = parse_properties(reference_text, "r.mtl");
    EXPECT_TRUE(parsed.ok() && other.ok()) << text;
    if (!parsed.ok() || !other.ok()) return differ + 1;
    const Query& q = parsed.file.queries.at(0);
    const Query& r = other.file.queries.at(0);
    const Bindings bindings{{"k", static_cast<double>(c % 5)}};
    EXPECT_TRUE(OperatorMonitor::accepts(*q.formula)) << text;
    OperatorMonitor fast(*q.formula, kTicks, bindings, q.run);
    OnlineMonitor general(*r.formula, kTicks, bindings, r.run);
    for (int k = 0; k < runs; ++k) {
      const Trace trace = random.trace();
      fast.reset();  // the same monitors judge every run, as in smc
      general.reset();
      const Judged got = judge(fast, trace), expected = judge(general, trace);
      if (got != expected) {
        ++differ;
        if (report-- > 0) {
          ADD_FAILURE() << text << " on " << describe(trace) << ": " << describe(got)
                        << ", expected " << describe(expected);
        }
      }
      ++tally.cases;
      (got.verdict == Verdict::True    ? tally.trues
       : got.verdict == Verdict::False ? tally.falses
                                       : tally.undecided) += 1;
      tally.early += got.decided_at >= 0;
      tally.hits += got.sure_hit != online::kForever;
    }
  }
  return differ;
}

TEST(OperatorMonitor, AgreesWithTheOnlineMonitorStepByStep) {
  // 4,000 formulas, 25 runs each.
  Tally tally;
  EXPECT_EQ(differences(20261126, 4000, 25, tally, 10), 0);
  // Every verdict, early decisions and first hits occur often enough to be compared.
  EXPECT_GT(tally.trues, 20000);
  EXPECT_GT(tally.falses, 20000);
  EXPECT_GT(tally.undecided, 5000);
  EXPECT_GT(tally.early, 30000);
  EXPECT_GT(tally.hits, 10000);
}

const std::string& shifted(const std::string& text) {
  // The same query with every bound one tick longer: "[a,b]" becomes "[a,b+1]".
  static std::string result;
  result.clear();
  for (std::size_t i = 0; i < text.size(); ++i) {
    result += text[i];
    if (text[i] == ',' && i > 0 && std::isdigit(static_cast<unsigned char>(text[i - 1]))) {
      std::size_t end = i + 1;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      result += std::to_string(std::stoi(text.substr(i + 1, end - i - 1)) + 1);
      i = end - 1;
    }
  }
  return result;
}

TEST(OperatorMonitor, ComparisonsOrderValuesAsTheGeneralMonitorDoes) {
  // Each comparison over a value below, at and above its number, and NaN (unordered: only !=
  // holds), alone and joined by && and ||.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int compared = 0;
  for (const char* op : {"<", "<=", ">", ">=", "==", "!="}) {
    for (const std::string& form : {std::string("x OP 1"), std::string("x OP 1 && x OP 1"),
                                    std::string("x OP 1 || p OP 2")}) {
      std::string state = form;
      for (std::size_t at; (at = state.find("OP")) != std::string::npos;) state.replace(at, 2, op);
      const std::string text = "P=? [ F (" + state + ") ]";
      const ParsedProperties parsed = parse_properties(text, "q.mtl");
      ASSERT_TRUE(parsed.ok()) << text;
      const Formula& formula = *parsed.file.queries.at(0).formula;
      ASSERT_TRUE(OperatorMonitor::accepts(formula)) << text;
      OperatorMonitor fast(formula, kTicks, {}, {});
      OnlineMonitor general(formula, kTicks, {}, {});
      for (double x : {0.0, 1.0, 2.0, nan}) {
        Trace trace;
        trace.steps.push_back({0, {{"p", nan}, {"q", 0}, {"x", x}}});
        fast.reset();
        general.reset();
        EXPECT_EQ(judge(fast, trace), judge(general, trace)) << text << " at x = " << x;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 6 * 3 * 4);
}

TEST(OperatorMonitor, TheComparisonTellsBoundsOneTickApart) {
  // The comparison above would catch a monitor off by one tick at its windows' ends: against
  // the same queries with windows one tick longer, many cases differ.
  Tally tally;
  EXPECT_GT(differences(20261126, 400, 25, tally, 0, shifted), 300);
}

TEST(OperatorMonitor, EmptyRunsAndRunsOfOneStep) {
  const ParsedProperties parsed = parse_properties("P=? [ F[0,2] p ]", "q.mtl");
  ASSERT_TRUE(parsed.ok());
  OperatorMonitor monitor(*parsed.file.queries.at(0).formula, kTicks, {});
  EXPECT_EQ(monitor.end(RunEnd::Deadlock), Verdict::Undecided);  // nothing was read
  EXPECT_FALSE(monitor.over());
  const Step on{5, {{"p", 1}}};
  EXPECT_EQ(monitor.step(StepView(on), on.time), Verdict::Undecided);
  EXPECT_EQ(monitor.end(RunEnd::Cut), Verdict::True);  // p at the run's first instant
  EXPECT_EQ(monitor.first_hit_for_sure(), online::kFirst);
  monitor.reset();
  const Step off{5, {{"p", 0}}};
  monitor.step(StepView(off), off.time);
  EXPECT_EQ(monitor.end(RunEnd::Timelock), Verdict::Undecided);
  monitor.reset();
  monitor.step(StepView(off), off.time);
  EXPECT_EQ(monitor.end(RunEnd::Absorbing), Verdict::False);  // off forever
}

TEST(OperatorMonitor, TakesOneOperatorOverPlacesAndData) {
  for (const char* taken : {"F p", "G[0,5] (p && !q)", "!(p U[1,2] q)", "!!(p R q)",
                            "F (x / 2 > k)", "G (init -> p)"}) {
    const ParsedProperties parsed = parse_properties(std::string("P=? [ ") + taken + " ]", "q");
    ASSERT_TRUE(parsed.ok()) << taken;
    EXPECT_TRUE(OperatorMonitor::accepts(*parsed.file.queries.at(0).formula)) << taken;
  }
  for (const char* other : {"p", "X p", "F{3} p", "F G p", "F p && G q", "F[0,2] (p U q)",
                            "F time > 3", "F fired(go)", "G !deadlock", "F timelock"}) {
    const ParsedProperties parsed = parse_properties(std::string("P=? [ ") + other + " ]", "q");
    ASSERT_TRUE(parsed.ok()) << other;
    EXPECT_FALSE(OperatorMonitor::accepts(*parsed.file.queries.at(0).formula)) << other;
  }
}

}  // namespace
}  // namespace smcbip::monitors
