// The encoding of compiled guards and actions into Z3, checked against the engines' evaluator
// of the same code: what the encoding states exactly agrees with every execution, and what it
// leaves unknown is left free.
#include "fdir/smt/code_encoding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "tests/engines/temp_model.h"

namespace smcbip::fdir {
namespace {

const char* kModel = R"(package encoded
  port type P()
  connector type Solo(P p)
    define p
  end
  atom type A()
    data int x, y
    data bool b
    data float f
    export port P go()
    place s
    initial to s
    on go from s to s provided ((x > 2 && !b) || y == x % 4) do {
      if (x > y) then y = x - y; else y = y * 2; fi
      b = !b && x >= 0;
      f = f + 1.5;
      x = x / 3;
    }
  end
  compound type Top()
    component A a()
    connector Solo c(a.go)
  end
end
)";

/// Whether `claim` holds for every value of its free constants.
bool valid(z3::context& c, const z3::expr& claim) {
  z3::solver s(c);
  s.add(!claim);
  return s.check() == z3::unsat;
}

class CodeEncoding : public ::testing::Test {
 protected:
  void SetUp() override {
    system = tests::load_model_text(kModel, "Top()");
    ASSERT_TRUE(system);
    frame.data = {c.int_const("x"), c.int_const("y"), c.bool_const("b"), c.real_const("f")};
  }
  const bipc::ir::Transition& transition() const {
    return system->atom_types[system->atoms[0].type].transitions[0];
  }
  std::optional<bipc::ir::System> system;
  z3::context c;
  CodeFrame frame;
};

TEST_F(CodeEncoding, AGuardWithShortCircuitsAndModuloIsStatedExactlyOnNaturalNumbers) {
  CodeEncoder encoder(c);
  const z3::expr guard = encoder.expression(transition().guard, frame);
  const z3::expr x = c.int_const("x"), y = c.int_const("y"), b = c.bool_const("b");
  EXPECT_TRUE(valid(c, z3::implies(x >= 0, guard == ((x > 2 && !b) || y == z3::mod(x, 4)))));
  EXPECT_TRUE(valid(c, z3::implies(x > 2 && !b, guard)));
}

TEST_F(CodeEncoding, AnActionsBranchesBecomeIfThenElseAndFloatsStayUnknown) {
  CodeEncoder encoder(c);
  CodeFrame after = frame;
  encoder.statement(transition().action, after);
  const z3::expr x = c.int_const("x"), y = c.int_const("y"), b = c.bool_const("b");
  const z3::expr small = x >= -1000 && x <= 1000 && y >= -1000 && y <= 1000;
  EXPECT_TRUE(valid(c, z3::implies(small, after.data[1] == z3::ite(x > y, x - y, y * 2))));
  // Beyond 64 bits the engines wrap around: the encoding does not claim the exact value.
  EXPECT_FALSE(
      valid(c, z3::implies(y == c.int_val(std::numeric_limits<std::int64_t>::max()) && x < y,
                           after.data[1] == y * 2)));
  EXPECT_TRUE(valid(c, after.data[2] == (!b && x >= 0)));
  EXPECT_TRUE(valid(c, z3::implies(x >= 0, after.data[0] == x / 3)));
  // x / 3 on a negative x truncates in C++: the encoding leaves it unknown rather than wrong.
  EXPECT_FALSE(valid(c, z3::implies(x == -4, after.data[0] == -2)));
  EXPECT_FALSE(valid(c, z3::implies(x == -4, after.data[0] == -1)));
  EXPECT_TRUE(z3::eq(after.data[3], frame.data[3]));  // floats are not followed
  EXPECT_GT(encoder.fresh().size(), 0u);
}

}  // namespace
}  // namespace smcbip::fdir
