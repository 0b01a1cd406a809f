// The statistics of smc::check_properties end to end, on a BIP model whose run succeeds with a
// known probability p: two exponential racers of means A and B, the run succeeding when the
// first wins, p = B / (A + B). Each case repeats a whole check with seeds 1, 2, ... (200 times,
// 1,000 in the slow run) and compares the error rate with the method's bound plus three
// standard deviations of binomial slack (tests/smc/repetitions.h).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "tests/smc/check_fixtures.h"
#include "tests/smc/repetitions.h"

namespace smcbip::smc {
namespace {

/// models/two_exponentials.bip with means `a` and `b` ms: P(F judge.winner == 1) = b / (a + b).
const bipc::ir::System& race(int a, int b) {
  static std::map<std::pair<int, int>, std::optional<bipc::ir::System>> loaded;
  auto [it, fresh] = loaded.try_emplace(std::pair{a, b});
  if (fresh) {
    std::ifstream in(std::string(SMCBIP_SOURCE_DIR) + "/models/two_exponentials.bip");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto set = [&](const std::string& constant, int value) {
      const std::string line = "const data int " + constant + " = ";
      const std::size_t at = text.find(line);
      EXPECT_NE(at, std::string::npos) << constant;
      if (at == std::string::npos) return;
      text.replace(at, text.find('\n', at) - at, line + std::to_string(value));
    };
    set("MEAN_A", a);
    set("MEAN_B", b);
    it->second = smcbip::tests::load_model_text(text, "System()");
  }
  return *it->second;
}

/// How many of the repeated checks of `query` on race(a, b) answer `wrong` (a verdict, or for
/// an estimate whether its interval misses p).
int wrong_answers(int a, int b, const std::string& query, CheckOptions options,
                  std::optional<bool> wrong) {
  const bipc::ir::System& system = race(a, b);
  const monitors::PropertyFile file = tests::properties(query, system);
  const double p = static_cast<double>(b) / (a + b);
  int errors = 0;
  for (int r = 0; r < tests::repetitions(); ++r) {
    options.seed = 1 + static_cast<std::uint64_t>(r);
    const QueryResult result = check_properties(system, file, options).at(0);
    EXPECT_TRUE(result.error.empty()) << result.error;
    if (wrong) {
      errors += result.verdict == wrong;
    } else {
      errors += result.ci.low > p || result.ci.high < p;
    }
  }
  return errors;
}

TEST(BernoulliModel, SprtErrorsStayWithinAlphaAndBeta) {
  // theta = 0.5, delta = 0.05: p = 0.55 (means 9 and 11) is at the edge where P>= must hold,
  // p = 0.45 (11 and 9) where it must not.
  CheckOptions options;
  options.method = Method::Sprt;
  options.delta = 0.05;
  options.alpha = 0.05;
  options.beta = 0.1;
  options.threads = 1;
  const std::string query = "P>=0.5 [ F judge.winner == 1 ]\n";
  const int n = tests::repetitions();
  EXPECT_LE(wrong_answers(9, 11, query, options, false), tests::slack_bound(n, options.alpha));
  EXPECT_LE(wrong_answers(11, 9, query, options, true), tests::slack_bound(n, options.beta));
}

TEST(BernoulliModel, EstimatesCoverTheirProbability) {
  // p = 0.25 (means 30 and 10): PESTIM and the sequential interval at alpha 0.05.
  for (const Method method : {Method::Pestim, Method::Ci}) {
    CheckOptions options;
    options.method = method;
    options.delta = 0.05;
    options.alpha = 0.05;
    options.threads = 1;
    const int misses = wrong_answers(30, 10, "P=? [ F judge.winner == 1 ]\n", options, {});
    EXPECT_LE(misses, tests::slack_bound(tests::repetitions(), 0.05)) << method_name(method);
  }
}

}  // namespace
}  // namespace smcbip::smc
