// Actions of assignments from literals or from a datum plus or minus a literal
// (bipc/ir/simple_action.h), run straight on the slots (run_simple_action), leave every data slot
// and clock as the interpreter running their code does, to the bit, overflow wrapping included.
// Other shapes are not recognised.
#include "bipc/ir/simple_action.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#include "engines/interpreter/code_eval.h"
#include "engines/semantics/atom_steps.h"
#include "tests/engines/code_builders.h"

namespace smcbip::engines {
namespace {

using bipc::ir::Code;
using bipc::ir::Instr;
using bipc::ir::Op;
using bipc::ir::Scope;
using code_builders::push_float;
using code_builders::push_int;

Instr store(Scope scope, bipc::ir::Index index, ValueKind kind = ValueKind::Int) {
  Instr in = code_builders::load(scope, index, kind);
  in.op = Op::Store;
  return in;
}
Instr data(bipc::ir::Index slot) {
  return code_builders::load(Scope::AtomData, slot, ValueKind::Int);
}
Instr op(Op code, ValueKind kind = ValueKind::Int) { return code_builders::op(code, kind); }

class SimpleActionTest : public ::testing::Test {
 protected:
  /// Runs `action` both ways from the same slots, for several values of slot 0, and compares.
  void expect_agreement(const Code& action) {
    const auto simple = bipc::ir::simple_action(action);
    ASSERT_TRUE(simple);
    const std::int64_t starts[] = {0, -5, 7, std::numeric_limits<std::int64_t>::max(),
                                   std::numeric_limits<std::int64_t>::min()};
    for (std::int64_t start : starts) {
      Val by_code[3] = {make_int(start), make_int(3), make_float(0.5)};
      Val by_table[3] = {make_int(start), make_int(3), make_float(0.5)};
      ClockState clocks_code[2] = {{1.5, 10, 1.0}, {2.5, 20, 2.0}};
      ClockState clocks_table[2] = {{1.5, 10, 1.0}, {2.5, 20, 2.0}};
      eval_.execute(action, frame(by_code, clocks_code));
      run_simple_action(simple->data(), simple->data() + simple->size(),
                        frame(by_table, clocks_table));
      EXPECT_EQ(std::memcmp(by_code, by_table, sizeof by_code), 0) << start;
      EXPECT_EQ(std::memcmp(clocks_code, clocks_table, sizeof clocks_code), 0) << start;
    }
  }

  Frame frame(Val* slots, ClockState* clocks) {
    Frame f;
    f.atom_data = slots;
    f.atom_params = params_;
    f.clocks = clocks;
    f.clock_units = units_;
    f.now = 42;
    return f;
  }

  bipc::ir::System system_;
  BoundFunctions functions_;
  std::ostringstream out_;
  StringPool strings_;
  CallContext call_{out_, strings_};
  CodeEvaluator eval_{system_, functions_, call_};
  Val params_[1] = {make_int(2)};
  TimeValue units_[2] = {1, 1};
};

TEST_F(SimpleActionTest, IncrementsLiteralsAndClockResetsAgreeWithTheInterpreter) {
  // sc = sc + 1; x = 0;  (the literal folded to a float, or converted at run time)
  expect_agreement({{data(0), push_int(1), op(Op::Add), store(Scope::AtomData, 0), push_float(0.0),
                     store(Scope::Clock, 0, ValueKind::Float)}});
  // ph = 1; sc = sc - 1; y = 3;
  expect_agreement({{push_int(1), store(Scope::AtomData, 1), data(0), push_int(1), op(Op::Sub),
                     store(Scope::AtomData, 0), push_int(3), op(Op::IntToFloat, ValueKind::Float),
                     store(Scope::Clock, 1, ValueKind::Float)}});
  // a = b - (-4); b = a + 9; f = 2.25;  (a later statement reads an earlier one's store)
  expect_agreement({{data(1), push_int(-4), op(Op::Sub), store(Scope::AtomData, 0), data(0),
                     push_int(9), op(Op::Add), store(Scope::AtomData, 1), push_float(2.25),
                     store(Scope::AtomData, 2, ValueKind::Float)}});
  EXPECT_TRUE(bipc::ir::simple_action(Code{})->empty());
}

TEST_F(SimpleActionTest, OtherShapesAreNotRecognised) {
  // a = a * 2;  a = p + 1;  a = a + b;  a = a / 1;
  EXPECT_FALSE(
      bipc::ir::simple_action({{data(0), push_int(2), op(Op::Mul), store(Scope::AtomData, 0)}}));
  EXPECT_FALSE(bipc::ir::simple_action({{code_builders::load(Scope::AtomParam, 0, ValueKind::Int),
                                         push_int(1), op(Op::Add), store(Scope::AtomData, 0)}}));
  EXPECT_FALSE(
      bipc::ir::simple_action({{data(0), data(1), op(Op::Add), store(Scope::AtomData, 0)}}));
  // a connector's datum, a float sum, a rate
  EXPECT_FALSE(bipc::ir::simple_action({{push_int(1), store(Scope::ConnectorData, 0)}}));
  EXPECT_FALSE(bipc::ir::simple_action(
      {{code_builders::load(Scope::AtomData, 2, ValueKind::Float), push_float(1.0),
        op(Op::Add, ValueKind::Float), store(Scope::AtomData, 2, ValueKind::Float)}}));
  Instr rate = op(Op::StoreRate, ValueKind::Float);
  EXPECT_FALSE(bipc::ir::simple_action({{push_float(2.0), rate}}));
  // a trailing value with no store
  EXPECT_FALSE(bipc::ir::simple_action({{push_int(1)}}));
}

}  // namespace
}  // namespace smcbip::engines
