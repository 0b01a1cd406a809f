// ClockBounds finds the same dates as the interpreter's holds_when, and only for its form.
#include "engines/interpreter/clock_bounds.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <sstream>
#include <vector>

#include "engines/interpreter/code_eval.h"
#include "tests/engines/code_builders.h"

namespace smcbip::engines {
namespace {

using bipc::ir::Code;
using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;
using code_builders::push_float;
using code_builders::push_int;

Instr load(Scope scope, bipc::ir::Index index) {
  return code_builders::load(scope, index, ValueKind::Float);
}
Instr clock(bipc::ir::Index index) { return load(Scope::Clock, index); }
Instr op(Op code, ValueKind kind = ValueKind::Float) { return code_builders::op(code, kind); }
Instr data(bipc::ir::Index slot) { return load(Scope::AtomData, slot); }
Code conjunction(const Code& a, const Code& b) { return code_builders::joined(a, b); }

class ClockBoundsTest : public ::testing::Test {
 protected:
  /// The interpreter's and the bounds' dates agree over many clock states and dates.
  void expect_same_dates(const Code& code) {
    const std::optional<ClockBounds> bounds = ClockBounds::of(code);
    ASSERT_TRUE(bounds);
    std::mt19937_64 random(7);
    std::uniform_int_distribution<TimeValue> date(0, 50'000'000);
    std::uniform_real_distribution<double> value(0.0, 20.0);
    const double rates[] = {1.0, 2.0, 0.5, 0.0, -1.0, 1.0 / 3.0};
    for (int i = 0; i < 2000; ++i) {
      clocks_[0] = {value(random), date(random), rates[i % 6]};
      clocks_[1] = {value(random), date(random), rates[(i / 6) % 6]};
      Frame frame;
      frame.atom_data = data_;
      frame.clocks = clocks_;
      frame.clock_units = units_;
      frame.now = date(random);
      ASSERT_EQ(bounds->holds_when(frame), eval_.holds_when(code, frame)) << "state " << i;
    }
  }

  /// The same over clocks reset to 0 at rate 1 (the integer path of ClockBounds), at dates
  /// around those at which a clock reaches the literals 0 to 13, within and beyond 2^30 ns of
  /// its reset.
  void expect_same_dates_after_resets(const Code& code) {
    const std::optional<ClockBounds> bounds = ClockBounds::of(code);
    ASSERT_TRUE(bounds);
    std::mt19937_64 random(11);
    std::uniform_int_distribution<TimeValue> since(0, TimeValue{1} << 40);
    std::uniform_int_distribution<TimeValue> literal(0, 13), offset(-2, 2);
    const TimeValue spans[] = {0,
                               1'000,
                               TimeValue{1} << 29,
                               (TimeValue{1} << 30) - 1,
                               TimeValue{1} << 30,
                               TimeValue{1} << 35};
    for (int i = 0; i < 4000; ++i) {
      clocks_[0] = {0.0, since(random), 1.0};
      clocks_[1] = {0.0, since(random), 1.0};
      Frame frame;
      frame.atom_data = data_;
      frame.clocks = clocks_;
      frame.clock_units = units_;
      const bipc::ir::Index c = static_cast<bipc::ir::Index>(i % 2);
      frame.now = i % 3 == 0 ? clocks_[c].since + spans[(i / 3) % 6] + offset(random)
                             : clocks_[c].since + literal(random) * units_[c] + offset(random);
      ASSERT_EQ(bounds->holds_when(frame), eval_.holds_when(code, frame)) << "state " << i;
    }
  }

  bipc::ir::System system_;
  BoundFunctions functions_;
  std::ostringstream out_;
  StringPool strings_;
  CallContext call_{out_, strings_};
  CodeEvaluator eval_{system_, functions_, call_};
  Val data_[1] = {make_float(4.0)};
  ClockState clocks_[2];
  TimeValue units_[2] = {1'000'000, 1'000};  // milliseconds, microseconds
};

TEST_F(ClockBoundsTest, OneComparisonEitherWay) {
  for (Op cmp : {Op::Lt, Op::Le, Op::Gt, Op::Ge, Op::Eq}) {
    expect_same_dates({{clock(0), push_float(3.0), op(cmp)}});
    expect_same_dates({{push_float(2.5), clock(1), op(cmp)}});
    expect_same_dates({{clock(1), push_int(7), op(Op::IntToFloat), op(cmp)}});
  }
}

TEST_F(ClockBoundsTest, ChainsOfConjunctions) {
  const Code low{{clock(0), push_float(1.0), op(Op::Ge)}};
  const Code high{{clock(0), push_float(5.0), op(Op::Le)}};
  const Code other{{push_float(12.0), clock(1), op(Op::Gt)}};
  expect_same_dates(conjunction(low, high));
  expect_same_dates(conjunction(conjunction(low, high), other));
  expect_same_dates(conjunction(conjunction(other, high), low));
}

TEST_F(ClockBoundsTest, ResetClocksGiveTheInterpretersDates) {
  for (Op cmp : {Op::Lt, Op::Le, Op::Gt, Op::Ge, Op::Eq}) {
    expect_same_dates_after_resets({{clock(0), push_int(5), op(Op::IntToFloat), op(cmp)}});
    expect_same_dates_after_resets({{push_float(13.0), clock(1), op(cmp)}});
    expect_same_dates_after_resets({{clock(1), push_float(2.5), op(cmp)}});
  }
  const Code low{{clock(0), push_float(1.0), op(Op::Ge)}};
  const Code high{{clock(0), push_int(5), op(Op::IntToFloat), op(Op::Le)}};
  const Code other{{push_float(12.0), clock(1), op(Op::Gt)}};
  expect_same_dates_after_resets(conjunction(low, high));
  expect_same_dates_after_resets(conjunction(conjunction(other, high), low));
}

TEST_F(ClockBoundsTest, OtherFormsAreLeftToTheInterpreter) {
  const Code low{{clock(0), push_float(1.0), op(Op::Ge)}};
  const Code by_data{{clock(0), data(0), op(Op::Le)}};
  EXPECT_FALSE(ClockBounds::of(Code{}));
  EXPECT_FALSE(ClockBounds::of(by_data));
  EXPECT_FALSE(ClockBounds::of(conjunction(low, by_data)));
  Code disjunction = conjunction(low, low);
  disjunction.instrs[3].op = Op::JumpIfTrueKeep;
  EXPECT_FALSE(ClockBounds::of(disjunction));
  // `a && (b && c)`: both jumps land at the end.
  Code right_nested = conjunction(low, conjunction(low, low));
  EXPECT_FALSE(ClockBounds::of(right_nested));
  EXPECT_FALSE(ClockBounds::of({{clock(0), clock(1), op(Op::Le)}}));
}

}  // namespace
}  // namespace smcbip::engines
