// The offers OfferMemo keeps are those the interpreter computes (interpreted_offers), on every
// state of a grid of data values, places and parameters, including a non-deterministic one; the
// types it must not keep (a guard the interpreter decides, a clock guard, more than one place
// marked, no comparison) are not kept; and a type whose values do not repeat stops being kept.
#include "engines/semantics/offer_memo.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_steps.h"
#include "engines/semantics/layout.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

// Queue: guards of leading comparisons alone, over data and a parameter, in two places; at
// n == 5 in A, p and q both offer p's transitions (two of them): a non-deterministic choice.
// Sum, Timed, Net, Plain: a guard the comparisons do not decide, a clock guard, a net with two
// places marked at once, no comparison at all.
constexpr const char* kModel = R"(package memo
  port type Sig()
  atom type Queue(int c)
    data int n, ph
    port Sig p(), q(), r()
    place A, B
    initial to A do { n = 0; ph = 1; }
    on p from A to A provided (n < c) do { n = n + 1; }
    on q from A to A provided (n > 0 && ph == 1) do { ph = 2; }
    on r from A to B provided (n > 0 && ph == 2) do { n = n - 1; ph = 1; }
    on p from A to A provided (n == 5) do { n = 0; }
    on q from B to A provided (ph != 1)
    on p from B to B
  end
  atom type Sum()
    data int n
    port Sig p()
    place A
    initial to A do { n = 0; }
    on p from A to A provided (n > 0 && n + 1 > 2) do { n = n - 1; }
  end
  atom type Timed()
    data int n
    clock x unit millisecond
    port Sig p()
    place A
    initial to A do { n = 0; x = 0; }
    on p from A to A provided (n > 0 && x > 2) do { n = n - 1; }
  end
  atom type Net()
    data int n
    port Sig p()
    place A, B
    initial to A, B do { n = 0; }
    on p from A, B to A, B provided (n == 0)
  end
  atom type Plain()
    port Sig p()
    place A, B
    initial to A
    on p from A to B
    on p from B to A
  end
  compound type Top()
    component Queue s(7)
    component Sum u()
    component Timed t()
    component Net w()
    component Plain v()
  end
end
)";

class OfferMemoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    system_ = tests::load_model_text(kModel, "Top()");
    ASSERT_TRUE(system_);
    ASSERT_EQ(build_layout(*system_, layout_), "");
  }
  bipc::ir::Index type_of(const char* name) const {
    for (bipc::ir::Index t = 0; t < system_->atom_types.size(); ++t) {
      if (system_->atom_types[t].name == std::string("memo.") + name) return t;
    }
    ADD_FAILURE() << "no type " << name;
    return 0;
  }
  Frame frame(std::vector<Val>& data, std::vector<Val>& params) const {
    Frame f;
    f.atom_data = data.data();
    f.atom_params = params.data();
    return f;
  }

  std::optional<bipc::ir::System> system_;
  Layout layout_;
  BoundFunctions functions_;
  std::ostringstream out_;
  StringPool strings_;
  CallContext call_{out_, strings_};
};

TEST_F(OfferMemoTest, KeepsOnlyStateMachinesGuardedByTheirComparisons) {
  const OfferMemo memo(*system_, layout_);
  EXPECT_TRUE(memo.keeps(type_of("Queue")));
  EXPECT_FALSE(memo.keeps(type_of("Sum")));
  EXPECT_FALSE(memo.keeps(type_of("Timed")));
  EXPECT_FALSE(memo.keeps(type_of("Net")));
  EXPECT_FALSE(memo.keeps(type_of("Plain")));
}

TEST_F(OfferMemoTest, GivesTheOffersTheInterpreterComputes) {
  CodeEvaluator eval(*system_, functions_, call_);
  OfferMemo memo(*system_, layout_);
  const bipc::ir::Index type = type_of("Queue");
  const std::size_t ports = system_->atom_types[type].ports.size();
  int kept = 0, nondeterministic = 0;
  // Twice over the grid: the first pass fills the memo, the second finds what it kept.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::int64_t c : {0, 3, 7}) {
      for (std::uint8_t place = 0; place < 2; ++place) {
        for (std::int64_t n = -2; n <= 9; ++n) {
          for (std::int64_t ph = 0; ph <= 3; ++ph) {
            std::vector<Val> data{make_int(n), make_int(ph)}, params{make_int(c)};
            const std::vector<std::uint8_t> marking{static_cast<std::uint8_t>(place == 0),
                                                    static_cast<std::uint8_t>(place == 1)};
            const Frame f = frame(data, params);
            std::vector<std::optional<AtomPortValue>> expected(ports), found(ports);
            const bipc::ir::Index result = interpreted_offers(
                *system_, layout_, type, marking.data(), f, eval, expected.data());
            bipc::ir::Index memo_result = bipc::ir::kNone;
            const bool hit = memo.find(type, marking.data(), f, found.data(), memo_result);
            if (!hit) {
              for (const auto& offer : found) EXPECT_FALSE(offer);  // untouched on a miss
              memo.remember(type, marking.data(), f, expected.data(), result);
              ASSERT_TRUE(memo.find(type, marking.data(), f, found.data(), memo_result));
            }
            kept += hit ? 1 : 0;
            nondeterministic += result != bipc::ir::kNone ? 1 : 0;
            EXPECT_EQ(memo_result, result) << "n " << n << ", ph " << ph << ", c " << c;
            for (std::size_t p = 0; p < ports; ++p) {
              ASSERT_EQ(found[p].has_value(), expected[p].has_value()) << "port " << p;
              if (!expected[p]) continue;
              EXPECT_EQ(found[p]->transition, expected[p]->transition);
              EXPECT_EQ(found[p]->constraint.interval, expected[p]->constraint.interval);
              EXPECT_EQ(found[p]->constraint.urgency, expected[p]->constraint.urgency);
            }
          }
        }
      }
    }
  }
  EXPECT_GT(kept, 0);
  EXPECT_GT(nondeterministic, 0);
}

TEST_F(OfferMemoTest, StopsKeepingATypeWhoseValuesDoNotRepeat) {
  CodeEvaluator eval(*system_, functions_, call_);
  OfferMemo memo(*system_, layout_);
  const bipc::ir::Index type = type_of("Queue");
  const std::vector<std::uint8_t> marking{1, 0};
  std::vector<std::optional<AtomPortValue>> offers(system_->atom_types[type].ports.size());
  for (std::int64_t n = 0; n < 10000 && memo.keeps(type); ++n) {
    std::vector<Val> data{make_int(n), make_int(1)}, params{make_int(7)};
    const Frame f = frame(data, params);
    bipc::ir::Index result = bipc::ir::kNone;
    if (memo.find(type, marking.data(), f, offers.data(), result)) continue;
    result = interpreted_offers(*system_, layout_, type, marking.data(), f, eval, offers.data());
    memo.remember(type, marking.data(), f, offers.data(), result);
  }
  EXPECT_FALSE(memo.keeps(type));
}

}  // namespace
}  // namespace smcbip::engines
