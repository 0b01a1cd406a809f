// Conformance oracles of EXPECTED.md section 11: models without an original test, with
// hand-derived expectations (random runs and --explore state counts).
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tests/engines/conformance_suite.h"
#include "tests/engines/trace_oracles.h"

namespace smcbip::tests {
namespace {

using engines::kRunOk;

template <class Engine>
class ConformanceHandDerived : public ConformanceFixture<Engine> {};
TYPED_TEST_SUITE(ConformanceHandDerived, AllModels, EngineNames);

/// Random run of a counter atom: `steps` internal-port steps, then a deadlock.
void expect_internal_counting(const ConformanceRun& run, std::uint64_t steps) {
  static const std::regex internal_ports("^[0-9]+ internal ports?:$");
  EXPECT_EQ(run.result.code, kRunOk);
  EXPECT_EQ(choose_lines(run.lines).size(), steps);
  const std::vector<StateHeader> headers = state_headers(run.lines);
  ASSERT_EQ(headers.size(), steps + 1);
  for (std::uint64_t n = 0; n < steps; ++n) {
    ASSERT_EQ(headers[n].state, n);
    ASSERT_TRUE(std::regex_match(headers[n].summary, internal_ports))
        << "state " << n << ": " << headers[n].summary;
  }
  EXPECT_EQ(state_header(run.lines, steps), "deadlock!");
}

/// An --explore run's summary: S states, D deadlocks, E errors.
void expect_exploration(const ConformanceRun& run, std::uint64_t states, std::uint64_t deadlocks,
                        std::uint64_t errors) {
  EXPECT_EQ(run.result.code, kRunOk);
  const std::optional<ExplorationSummary> summary = exploration_summary(run.lines);
  ASSERT_TRUE(summary.has_value()) << "no exploration summary in:\n" << run.text;
  EXPECT_EQ(summary->states, states);
  EXPECT_EQ(summary->deadlocks, deadlocks);
  EXPECT_EQ(summary->errors, errors);
}

TYPED_TEST(ConformanceHandDerived, S11_doublecounter_random_run) {
  this->check_runs("running/doublecounter", "CT()", this->options(),
                   [](const auto& run) { expect_internal_counting(run, 200); });
}

TYPED_TEST(ConformanceHandDerived, S11_doublecounter_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/doublecounter", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 10201, 1, 0); });
}

// With --limit d, only the states within d steps: counters (i, j) with i + j <= d, that is
// (d + 1)(d + 2) / 2 of them for d <= 100, none a deadlock.
TYPED_TEST(ConformanceHandDerived, S11_doublecounter_explore_bounded_by_limit) {
  auto options = this->options();
  options.explore = true;
  options.limit = 10;
  this->check_runs("running/doublecounter", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 66, 0, 0); });
}

TYPED_TEST(ConformanceHandDerived, S11_doublecounter2_random_run) {
  this->check_runs("running/doublecounter2", "CT()", this->options(),
                   [](const auto& run) { expect_internal_counting(run, 200); });
}

TYPED_TEST(ConformanceHandDerived, S11_doublecounter2_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/doublecounter2", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 5251, 1, 0); });
}

TYPED_TEST(ConformanceHandDerived, S11_cyclic_random_run) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs("running/cyclic", "CT()", options, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
    EXPECT_TRUE(lacks(run.lines, "deadlock"));
  });
}

// 201² states; 0 errors as in the multithread suite's bound-500 variant.
TYPED_TEST(ConformanceHandDerived, S11_cyclic_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/cyclic", "CT()", options, 1,
                   [](const auto& run) { expect_exploration(run, 40401, 0, 0); });
}

TYPED_TEST(ConformanceHandDerived, S11_dining_philo_random_run) {
  this->check_runs("running/dining_philo", "DiningPhilo()", this->options(), [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(last_state_header(run.lines), "deadlock!");
  });
}

// 7 philosophers (the documentation's example); 0 errors as in the 8-philosopher variant.
TYPED_TEST(ConformanceHandDerived, S11_dining_philo_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/dining_philo", "DiningPhilo()", options, 1,
                   [](const auto& run) { expect_exploration(run, 27303, 2, 0); });
}

TYPED_TEST(ConformanceHandDerived, S11_dining_philo_flat_random_run) {
  this->check_runs("running/dining_philo_flat", "DiningPhilo()", this->options(),
                   [](const auto& run) {
                     static const std::regex internal_ports("^[0-9]+ internal ports?:$");
                     EXPECT_EQ(run.result.code, kRunOk);
                     const std::vector<StateHeader> headers = state_headers(run.lines);
                     ASSERT_FALSE(headers.empty());
                     EXPECT_EQ(headers.back().summary, "deadlock!");
                     for (std::size_t i = 0; i + 1 < headers.size(); ++i) {
                       ASSERT_TRUE(std::regex_match(headers[i].summary, internal_ports))
                           << "state " << headers[i].state << ": " << headers[i].summary;
                     }
                   });
}

TYPED_TEST(ConformanceHandDerived, S11_dining_philo_flat_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running/dining_philo_flat", "DiningPhilo()", options, 1,
                   [](const auto& run) { expect_exploration(run, 117485, 2, 0); });
}

TYPED_TEST(ConformanceHandDerived, S11_priority_rules_guard) {
  this->check_runs("running/priority_rules_guard", "MyCompoundType()", this->options(),
                   [](const auto& run) {
                     EXPECT_EQ(run.result.code, kRunOk);
                     for (std::uint64_t n = 0; n <= 7; ++n) {
                       EXPECT_EQ(state_header(run.lines, n), "1 interaction:") << "state " << n;
                     }
                     EXPECT_EQ(state_header(run.lines, 8), "deadlock!");
                     const Lines choices = choose_lines(run.lines);
                     ASSERT_EQ(choices.size(), 8u);
                     for (std::size_t i = 0; i < choices.size(); ++i) {
                       const char* expected = i % 2 == 0 ? "ROOT.rdv2: " : "ROOT.rdv1: ";
                       EXPECT_TRUE(has(Lines{choices[i]}, expected)) << choices[i];
                     }
                   });
}

/// The atoms named in a choose line's port values, and its connector (`c1`..`c4`).
std::pair<std::string, std::string> conflicting_choice(const std::string& line) {
  static const std::regex choice(R"(-> choose \[[0-9]+\] ROOT\.(c[1-4]): (.*) at global time )");
  static const std::regex entry(R"(\b([A-D])\.[pq]\(\))");
  std::smatch m;
  if (!std::regex_search(line, m, choice)) return {};
  const std::string values = m[2].str();
  std::set<char> atoms;
  for (auto it = std::sregex_iterator(values.begin(), values.end(), entry);
       it != std::sregex_iterator(); ++it) {
    atoms.insert((*it)[1].str()[0]);
  }
  return {m[1].str(), std::string(atoms.begin(), atoms.end())};
}

TYPED_TEST(ConformanceHandDerived, S11_conflicting) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs("running_multithread_extra/conflicting", "Comp()", options, [](const auto& run) {
    EXPECT_EQ(run.result.code, kRunOk);
    EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
    EXPECT_TRUE(lacks(run.lines, "deadlock"));
    // (A,B) and (C,D) only ever move together, by their own rendezvous.
    for (const std::string& line : choose_lines(run.lines)) {
      const auto [connector, atoms] = conflicting_choice(line);
      const bool ab = connector == "c1" || connector == "c3";
      ASSERT_EQ(atoms, connector.empty() ? "?" : ab ? "AB" : "CD") << line;
    }
  });
}

TYPED_TEST(ConformanceHandDerived, S11_non_conflicting) {
  auto options = this->options();
  options.limit = 1000;
  this->check_runs(
      "running_multithread_extra/non_conflicting", "Comp()", options, [](const auto& run) {
        EXPECT_EQ(run.result.code, kRunOk);
        const std::vector<StateHeader> headers = state_headers(run.lines);
        ASSERT_EQ(headers.size(), 1001u);
        for (std::uint64_t n = 0; n < 1000; ++n) {
          ASSERT_EQ(headers[n].state, n);
          ASSERT_EQ(headers[n].summary, "2 interactions:") << "state " << n;
        }
        EXPECT_EQ(state_header(run.lines, 1000), "stop (reached limit of 1000 states)");
      });
}

TYPED_TEST(ConformanceHandDerived, S11_non_conflicting_explore) {
  auto options = this->options();
  options.explore = true;
  this->check_runs("running_multithread_extra/non_conflicting", "Comp()", options, 1,
                   [](const auto& run) { expect_exploration(run, 4, 0, 0); });
}

}  // namespace
}  // namespace smcbip::tests
