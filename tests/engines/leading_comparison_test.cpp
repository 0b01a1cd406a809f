// The leading comparisons of a guard (bipc/ir/data_guard.h), tested straight from the atom's
// slots, agree with the interpreter: the guard is false whenever one of them is, and equal to
// their conjunction when they are the whole guard. Shapes where a false comparison does not
// decide the guard are not recognised.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <sstream>

#include "bipc/ir/data_guard.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_steps.h"
#include "tests/engines/code_builders.h"

namespace smcbip::engines {
namespace {

using bipc::ir::Code;
using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;
using code_builders::push_int;

Instr load(Scope scope, bipc::ir::Index index, ValueKind kind = ValueKind::Int) {
  return code_builders::load(scope, index, kind);
}
Instr op(Op code, ValueKind kind = ValueKind::Int) { return code_builders::op(code, kind); }
Instr data(bipc::ir::Index slot) { return load(Scope::AtomData, slot); }
Instr param(bipc::ir::Index slot) { return load(Scope::AtomParam, slot); }
Code conjunction(const Code& a, const Code& b) { return code_builders::joined(a, b); }
Code disjunction(const Code& a, const Code& b) {
  return code_builders::joined(a, b, Op::JumpIfTrueKeep);
}

constexpr Op kComparisons[] = {Op::Eq, Op::Ne, Op::Lt, Op::Le, Op::Gt, Op::Ge};

class LeadingComparisonTest : public ::testing::Test {
 protected:
  /// Over every value of data slots 0 and 1 in [-3, 3] (slot 2 and the parameter fixed), the
  /// guard never holds where the comparisons do not all hold, and equals their conjunction when
  /// they are the whole guard.
  void expect_agreement(const Code& guard, bool whole, std::size_t count = 1) {
    const auto leading = bipc::ir::leading_comparison(guard);
    ASSERT_TRUE(leading);
    EXPECT_EQ(leading->whole, whole);
    EXPECT_EQ(leading->count, count);
    for (std::int64_t a = -3; a <= 3; ++a) {
      for (std::int64_t b = -3; b <= 3; ++b) {
        data_[0] = make_int(a);
        data_[1] = make_int(b);
        Frame frame;
        frame.atom_data = data_;
        frame.atom_params = params_;
        const bool test = leading_holds(compile_leading(*leading), data_, params_);
        const bool holds = eval_.holds(guard, frame);
        if (!test) {
          EXPECT_FALSE(holds) << a << ", " << b;
        }
        if (whole) {
          EXPECT_EQ(test, holds) << a << ", " << b;
        }
      }
    }
  }

  bipc::ir::System system_;
  BoundFunctions functions_;
  std::ostringstream out_;
  StringPool strings_;
  CallContext call_{out_, strings_};
  CodeEvaluator eval_{system_, functions_, call_};
  Val data_[3] = {make_int(0), make_int(0), make_int(1)};
  Val params_[1] = {make_int(2)};
};

TEST_F(LeadingComparisonTest, WholeComparisonsOfDataParametersAndLiterals) {
  for (Op cmp : kComparisons) {
    expect_agreement({{data(0), push_int(1), op(cmp)}}, true);
    expect_agreement({{push_int(-2), data(1), op(cmp)}}, true);
    expect_agreement({{data(0), data(1), op(cmp)}}, true);
    expect_agreement({{param(0), data(0), op(cmp)}}, true);
    expect_agreement({{data(1), param(0), op(cmp)}}, true);
  }
}

TEST_F(LeadingComparisonTest, ConjunctionsOfComparisons) {
  const Code rest{{data(1), push_int(0), op(Op::Gt)}};
  const Code more{{data(2), push_int(1), op(Op::Eq)}};
  for (Op cmp : kComparisons) {
    const Code first{{data(0), push_int(1), op(cmp)}};
    expect_agreement(conjunction(first, rest), true, 2);
    expect_agreement(conjunction(conjunction(first, rest), more), true, 3);
  }
}

TEST_F(LeadingComparisonTest, ComparisonsLeadingOtherCode) {
  // `data1 + 1 > 0` is not a comparison of slots: the tests stop before it.
  const Code sum{{data(1), push_int(1), op(Op::Add), push_int(0), op(Op::Gt)}};
  const Code rest{{data(1), push_int(0), op(Op::Gt)}};
  for (Op cmp : kComparisons) {
    const Code first{{data(0), push_int(1), op(cmp)}};
    expect_agreement(conjunction(first, sum), false, 1);
    expect_agreement(conjunction(conjunction(first, rest), sum), false, 2);
  }
  // Beyond kMax comparisons the rest is left to the interpreter.
  Code chain{{data(0), push_int(1), op(Op::Ge)}};
  for (int k = 0; k < 5; ++k) chain = conjunction(chain, {{data(1), push_int(-k), op(Op::Gt)}});
  expect_agreement(chain, false, bipc::ir::LeadingComparison::kMax);
}

TEST_F(LeadingComparisonTest, ShapesAFalseComparisonDoesNotDecideAreRefused) {
  const Code first{{data(0), push_int(1), op(Op::Eq)}};
  const Code rest{{data(1), push_int(0), op(Op::Gt)}};
  // (first && rest) || rest: a false `first` still leaves the disjunction to decide.
  EXPECT_FALSE(bipc::ir::leading_comparison(disjunction(conjunction(first, rest), rest)));
  EXPECT_FALSE(bipc::ir::leading_comparison(disjunction(first, rest)));
  // Not integer comparisons of slots the test reads.
  Instr to_float = op(Op::IntToFloat, ValueKind::Float);
  EXPECT_FALSE(
      bipc::ir::leading_comparison({{data(0), to_float, load(Scope::AtomData, 1, ValueKind::Float),
                                     op(Op::Lt, ValueKind::Float)}}));
  EXPECT_FALSE(
      bipc::ir::leading_comparison({{load(Scope::ConnectorData, 0), push_int(1), op(Op::Eq)}}));
  Instr element = data(0);
  element.arg = 1;
  EXPECT_FALSE(bipc::ir::leading_comparison({{element, push_int(1), op(Op::Eq)}}));
  EXPECT_FALSE(bipc::ir::leading_comparison({{data(0), push_int(1), op(Op::Add)}}));
  EXPECT_FALSE(bipc::ir::leading_comparison({}));
}

}  // namespace
}  // namespace smcbip::engines
