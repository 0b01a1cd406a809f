// Faults of a model's own code at run time (a division by zero, an extern function without an
// implementation, a transition that puts a second token in a place) are reported at the place
// in the model where they arise, on every engine.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "engines/engines.h"
#include "tests/engines/run_once.h"
#include "tests/engines/temp_model.h"

namespace smcbip::tests {
namespace {

using engines::EngineKind;

// Line and column of each fault are given beside it: the operator, the call, the transition.
constexpr const char* kModel = R"(package faults
  extern function int nothing_here(int)
  port type P()
  port type Q(int n)
  connector type Solo(P p)
    define p
  end
  connector type Guarded(Q q)
    define q
    on q provided (1 % q.n == 0)
  end
  atom type Divides()
    data int x = 3
    data int y = 2
    export port P p()
    place s
    initial to s
    on p from s to s
      do {
        y = y - 1;
        x = x / y;
      }
  end
  atom type Zero()
    data int zero = 0
    export port Q q(zero)
    place s
    initial to s
    on q from s to s
  end
  atom type Calls()
    data int v
    place s
    initial to s do { v = nothing_here(1); }
  end
  atom type Unsafe()
    export port P p()
    place a, b
    initial to a, b
    on p from a to b
  end
  compound type Division()
    component Divides d()
    connector Solo c(d.p)
  end
  compound type Modulo()
    component Zero z()
    connector Guarded c(z.q)
  end
  compound type Call()
    component Calls c()
  end
  compound type NotSafe()
    component Unsafe u()
    connector Solo c(u.p)
  end
end
)";

engines::RunResult run(const bipc::ir::System& system, EngineKind engine) {
  return run_once(system, engine, 3, 20);
}

struct Fault {
  const char* root;
  const char* where;    // after the model's path
  const char* message;  // the start of the message
};

TEST(ModelFaults, NameTheirPlaceInTheModel) {
  const TempDir dir;
  const std::string file = dir.write("faults.bip", kModel).string();
  for (const Fault& fault : {Fault{"Division()", ":21:15", "division by zero"},
                             Fault{"Modulo()", ":10:22", "modulo by zero"},
                             Fault{"Call()", ":34:27", "extern function nothing_here(int)"},
                             Fault{"NotSafe()", ":40:5", "the Peri net of ROOT.u is not 1-safe"}}) {
    SCOPED_TRACE(fault.root);
    const std::optional<bipc::ir::System> system = load_model(file, fault.root);
    ASSERT_TRUE(system);
    for (EngineKind engine :
         {EngineKind::Reference, EngineKind::Optimised, EngineKind::Multithread}) {
      const engines::RunResult result = run(*system, engine);
      EXPECT_EQ(result.end, engines::RunEnd::Error);
      EXPECT_EQ(result.where, file + fault.where) << result.message;
      EXPECT_TRUE(result.message.starts_with(fault.message)) << result.message;
    }
  }
}

}  // namespace
}  // namespace smcbip::tests
