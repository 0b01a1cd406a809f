// The builtin printf of interpreted models: BIP values through C's conversions, and nothing a
// model writes in its format (`%n`, `%*d`, a stray `%`) reaches C's printf unchecked. And a
// simulator keeps the extern functions it is given.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "engines/api/externs.h"
#include "engines/engines.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

/// printf's output for `format` and the arguments of these kinds.
std::string printed(const std::string& format, const std::vector<ValueKind>& kinds,
                    const std::vector<Val>& values) {
  static const Externs builtins = Externs::with_builtins();
  StringPool strings;
  std::ostringstream out;
  std::vector<ValueKind> all{ValueKind::String};
  for (ValueKind k : kinds) all.push_back(k);  // (gcc 12 warns falsely on insert of 1-byte items)
  const Externs::Function* printf = builtins.find("printf", all);
  EXPECT_NE(printf, nullptr);
  if (printf == nullptr) return {};
  std::vector<Val> args{Val{}};
  args[0].s = strings.intern(format);
  for (const Val& v : values) args.push_back(v);
  CallContext context{out, strings, nullptr, all};
  printf->fn(context, args);
  return out.str();
}

TEST(BuiltinPrintf, PrintsBipValuesThroughCConversions) {
  EXPECT_EQ(
      printed("%d|%5.2f|%s|%x", {ValueKind::Int, ValueKind::Float, ValueKind::Bool, ValueKind::Int},
              {make_int(-7), make_float(3.14159), make_bool(true), make_int(255)}),
      "-7| 3.14|true|ff");
  EXPECT_EQ(printed("%d and %ld", {ValueKind::Bool, ValueKind::Int},
                    {make_bool(false), make_int(1LL << 40)}),
            "0 and 1099511627776");
}

TEST(BuiltinPrintf, WhatPrintsNoValueIsPrintedAsWritten) {
  EXPECT_EQ(printed("100%", {}, {}), "100%");
  EXPECT_EQ(printed("100%\n", {}, {}), "100%\n");
  EXPECT_EQ(printed("50%% of %d", {ValueKind::Int}, {make_int(8)}), "50% of 8");
  // %n would write through the value as a pointer; %*d would read a width never passed.
  EXPECT_EQ(printed("a%nb", {ValueKind::Int}, {make_int(0x1234)}), "a%nb");
  EXPECT_EQ(printed("[%*d]", {ValueKind::Int}, {make_int(5)}), "[%*d]");
  EXPECT_EQ(printed("%d %d", {ValueKind::Int}, {make_int(1)}), "1 %d");  // no second value
  EXPECT_EQ(
      printed("%hhd|%Lf", {ValueKind::Int, ValueKind::Float}, {make_int(300), make_float(0.5)}),
      "300|0.500000");  // the length modifiers are printf's own choice
}

}  // namespace
}  // namespace smcbip::engines

namespace smcbip::engines {
namespace {

/// An atom that doubles its data through the extern function `twice` at each step and prints it.
auto doubling_model() {
  return tests::load_model_text(R"(package p
  extern function int twice(int)
  extern function printf(string, int)
  port type Port()
  atom type A()
    data int x = 1
    export port Port go()
    place S
    initial to S
    on go from S to S do { x = twice(x); printf("%d\n", x); }
  end
  connector type Solo(Port p)
    define p
  end
  compound type Top()
    component A a()
    connector Solo c(a.go)
  end
end
)",
                                "Top()");
}

Externs with_twice() {
  Externs externs = Externs::with_builtins();
  externs.add("twice", [](std::int64_t x) { return 2 * x; });
  return externs;
}

TEST(SimulatorExterns, ARegistryThatDoesNotOutliveTheSimulatorIsFine) {
  const auto system = doubling_model();
  ASSERT_TRUE(system);
  SimulateOptions options;
  options.seed = 1;
  options.limit = 3;
  Simulator simulator(*system, options, with_twice());  // the registry dies here
  std::ostringstream trace, output;
  const RunResult result = simulator.run(0, RunStreams{trace, output});
  EXPECT_EQ(result.code, kRunOk) << result.message;
  EXPECT_EQ(output.str(), "2\n4\n8\n");
}

TEST(SimulatorExterns, AnExternFaultEndsTheRunInAModelErrorAtTheCall) {
  const auto system = doubling_model();
  ASSERT_TRUE(system);
  Externs externs = Externs::with_builtins();
  externs.add("twice", [](std::int64_t x) -> std::int64_t {
    if (x >= 4) throw ExternFault("too large to double");
    return 2 * x;
  });
  SimulateOptions options;
  options.seed = 1;
  options.limit = 10;
  Simulator simulator(*system, options, externs);
  std::ostringstream trace, output;
  const RunResult result = simulator.run(0, RunStreams{trace, output});
  EXPECT_EQ(result.code, kInputError) << result.message;
  EXPECT_NE(result.message.find("twice: too large to double"), std::string::npos) << result.message;
  EXPECT_EQ(output.str(), "2\n4\n");  // the third step calls twice(4)
}

}  // namespace
}  // namespace smcbip::engines
