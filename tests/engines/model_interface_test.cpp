// The model interface: a model whose code is written in C++ (as generated models will be) runs
// through the same semantics and schedulers as the interpreted one, and gives the same runs.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "engines/engines.h"
#include "engines/interpreter/code_eval.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

// A counter that ticks every 2 to 4 ms until it reaches a bound, and a watcher that takes each
// value it announces, with a connector guard and data transfer.
constexpr const char* kModel = R"(package counting
  port type Num(int v)
  connector type Pass(Num src, Num dst)
    define src dst
    on src dst provided (src.v % 2 == 0) down { dst.v = src.v; }
  end
  atom type Counter(int bound)
    data int n
    clock x unit millisecond
    export port Num tick(n)
    place RUN, DONE
    initial to RUN do { n = 0; x = 0; }
    on tick from RUN to RUN provided (n < bound && x >= 2 && x <= 4) do { n = n + 2; x = 0; }
    internal from RUN to DONE provided (n >= bound)
  end
  atom type Watcher()
    data int seen, last
    export port Num take(last)
    place W
    initial to W do { seen = 0; last = -1; }
    on take from W to W do { seen = seen + 1; }
  end
  compound type Top()
    component Counter c(10)
    component Watcher w()
    connector Pass p(c.tick, w.take)
  end
end
)";

/// Every Code of the system, to check the numbering.
std::vector<const bipc::ir::Code*> all_code(const bipc::ir::System& s) {
  std::vector<const bipc::ir::Code*> out;
  for (const auto& type : s.atom_types) {
    for (const auto& d : type.data) out.push_back(&d.initial_value);
    out.push_back(&type.initial_action);
    for (const auto& t : type.transitions) {
      out.push_back(&t.guard);
      out.push_back(&t.action);
    }
    for (const auto& inv : type.invariants) out.push_back(&inv.guard);
  }
  for (const auto& type : s.connector_types) {
    for (const auto& code : type.interactions) {
      out.insert(out.end(), {&code.guard, &code.up, &code.down});
    }
  }
  return out;
}

TEST(ModelInterface, EveryCodeHasItsOwnNumber) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kModel, "Top()");
  ASSERT_TRUE(system);
  std::set<std::uint32_t> ids;
  for (const bipc::ir::Code* code : all_code(*system)) {
    EXPECT_LT(code->id, system->code_count);
    EXPECT_TRUE(ids.insert(code->id).second) << "id " << code->id << " twice";
  }
}

/// Code written by hand for kModel, found by Code::id as a generated model finds its compiled
/// functions; it counts its calls so that the test knows it is the one that ran.
class HandWrittenCode final : public ModelCode {
 public:
  using Fn = std::function<Val(const Frame&)>;
  HandWrittenCode(std::map<std::uint32_t, Fn> expressions, std::map<std::uint32_t, Fn> blocks,
                  std::map<std::uint32_t, std::function<Interval(const Frame&)>> windows,
                  int& calls)
      : expressions_(std::move(expressions)),
        blocks_(std::move(blocks)),
        windows_(std::move(windows)),
        calls_(calls) {}
  Val evaluate(const bipc::ir::Code& code, const Frame& frame) override {
    ++calls_;
    return code.empty() ? make_bool(true) : expressions_.at(code.id)(frame);
  }
  void execute(const bipc::ir::Code& code, const Frame& frame) override {
    ++calls_;
    if (!code.empty()) blocks_.at(code.id)(frame);
  }
  Interval holds_when(const bipc::ir::Code& code, const Frame& frame) override {
    ++calls_;
    return code.empty() ? Interval::all() : windows_.at(code.id)(frame);
  }

 private:
  std::map<std::uint32_t, Fn> expressions_, blocks_;
  std::map<std::uint32_t, std::function<Interval(const Frame&)>> windows_;
  int& calls_;
};

/// kModel with its code in C++. Data slots: Counter n = 0; Watcher seen = 0, last = 1; clock
/// x = 0 of Counter (milliseconds); Counter parameter bound = 0.
class HandWrittenModel final : public Model {
 public:
  explicit HandWrittenModel(const bipc::ir::System& system) : system_(system) {}
  const bipc::ir::System& system() const override { return system_; }
  std::unique_ptr<ModelCode> make_code(const BoundFunctions&, CallContext&) const override {
    const auto& counter = type("counting.Counter");
    const auto& watcher = type("counting.Watcher");
    const auto& pass = system_.connector_types.at(0).interactions.at(0);
    constexpr TimeValue kMs = 1'000'000;
    auto set = [](Val& slot, std::int64_t v) { slot = make_int(v); };
    std::map<std::uint32_t, HandWrittenCode::Fn> expressions, blocks;
    std::map<std::uint32_t, std::function<Interval(const Frame&)>> windows;
    blocks[counter.initial_action.id] = [=](const Frame& f) {
      set(f.atom_data[0], 0);
      f.clocks[0] = ClockState{0.0, f.now, 1.0};
      return Val{};
    };
    blocks[counter.transitions[0].action.id] = [=](const Frame& f) {
      set(f.atom_data[0], f.atom_data[0].i + 2);
      f.clocks[0] = ClockState{0.0, f.now, 1.0};
      return Val{};
    };
    windows[counter.transitions[0].guard.id] = [=](const Frame& f) {
      if (f.atom_data[0].i >= f.atom_params[0].i) return Interval::none();
      const TimeValue reset =
          f.clocks[0].since - static_cast<TimeValue>(f.clocks[0].value_at * kMs);
      return Interval{reset + 2 * kMs, reset + 4 * kMs, false, false};
    };
    windows[counter.transitions[1].guard.id] = [=](const Frame& f) {
      return f.atom_data[0].i >= f.atom_params[0].i ? Interval::all() : Interval::none();
    };
    expressions[counter.transitions[1].guard.id] = [=](const Frame& f) {
      return make_bool(f.atom_data[0].i >= f.atom_params[0].i);
    };
    blocks[watcher.initial_action.id] = [=](const Frame& f) {
      set(f.atom_data[0], 0);
      set(f.atom_data[1], -1);
      return Val{};
    };
    blocks[watcher.transitions[0].action.id] = [=](const Frame& f) {
      set(f.atom_data[0], f.atom_data[0].i + 1);
      return Val{};
    };
    expressions[pass.guard.id] = [](const Frame& f) {
      return make_bool(f.port_slot(f.port_context, 0, 0)->i % 2 == 0);
    };
    blocks[pass.down.id] = [](const Frame& f) {
      *f.port_slot(f.port_context, 1, 0) = *f.port_slot(f.port_context, 0, 0);
      return Val{};
    };
    return std::make_unique<HandWrittenCode>(expressions, blocks, windows, calls);
  }
  mutable int calls = 0;

 private:
  const bipc::ir::AtomType& type(const std::string& name) const {
    for (const auto& t : system_.atom_types) {
      if (t.name == name) return t;
    }
    throw std::runtime_error("no atom type " + name);
  }
  const bipc::ir::System& system_;
};

std::string run_trace(Simulator& simulator) {
  std::ostringstream out;
  const RunResult result = simulator.run(0, RunStreams{out, out});
  EXPECT_EQ(result.code, kRunOk) << result.message;
  return out.str();
}

TEST(ModelInterface, CodeWrittenInCppRunsLikeTheInterpretedModel) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kModel, "Top()");
  ASSERT_TRUE(system);
  HandWrittenModel compiled(*system);
  for (EngineKind engine :
       {EngineKind::Reference, EngineKind::Optimised, EngineKind::Multithread}) {
    SimulateOptions options;
    options.engine = engine;
    options.threads = 2;
    options.seed = 7;
    Simulator interpreted_run(*system, options, Externs::with_builtins());
    Simulator compiled_run(compiled, options, Externs::with_builtins());
    const std::string expected = run_trace(interpreted_run);
    compiled.calls = 0;
    EXPECT_EQ(run_trace(compiled_run), expected);
    EXPECT_GT(compiled.calls, 10) << "the hand-written code ran";
    EXPECT_NE(expected.find("deadlock"), std::string::npos) << expected;
  }
}

}  // namespace
}  // namespace smcbip::engines
