// always_changes_state (bipc/ir/state_change.h) checked against the interpreter: every
// transition it calls "always changes" is fired, by the interpreter, from many states where it
// is enabled (its `from` places marked, its guard true, data drawn at random and at the ends of
// the integers), and must leave its atom's places or data different. With a connector's `down`
// in between (data overwritten at random before the action), the transitions it still calls
// "always changes" must too. The check counts its firings, so it cannot pass by firing none.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bipc/ir/state_change.h"
#include "engines/interpreter/code_eval.h"
#include "engines/semantics/layout.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

using bipc::ir::AtomType;
using bipc::ir::Transition;

// Transitions of the shapes the analysis recognises, and near misses it must leave alone.
constexpr const char* kShapes = R"(package shapes
  port type Sig()
  atom type T(int k)
    data int n, m
    data bool b
    clock x unit millisecond
    port Sig p1(), p2(), p3(), p4(), p5(), p6(), p7(), p8(), p9()
    place A, B, C
    initial to A do { n = 0; m = 0; b = false; }
    on p1 from A to B
    on p2 from B to B provided (n == 2) do { n = 3; x = 0; }
    on p3 from B to B provided (m > 0 && n == 4) do { n = n + 0; n = 5; }
    on p4 from C to C do { n = n + 1; m = m - 1; }
    on p5 from C to C do { m = n + 2; n = m - 1; }
    on p6 from B to C provided (n < k) do { n = n * 2; }
    on p7 from A to A provided (n == 1) do { n = 1; }
    on p8 from A to A do { n = n + 1; n = n - 1; }
    on p9 from C to C provided (b) do { b = false; }
  end
  compound type Top()
    component T t(7)
  end
end
)";

class StateChangeSemantics : public ::testing::Test {
 protected:
  /// Fires every transition the analysis calls "always changes" in `system` from `tries` random
  /// enabled states; returns how many firings were checked.
  int check_system(const bipc::ir::System& system, int tries) {
    Layout layout;
    EXPECT_EQ(build_layout(system, layout), "");
    CodeEvaluator eval(system, functions_, call_);
    int fired = 0;
    for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
      const AtomType& type = system.atom_types[system.atoms[a].type];
      for (const Transition& transition : type.transitions) {
        for (const bool written_before : {false, true}) {
          if (!bipc::ir::always_changes_state(transition, written_before)) continue;
          const int before = fired;
          for (int i = 0; i < tries; ++i) {
            fired += fire_once(eval, layout, a, type, transition, written_before) ? 1 : 0;
          }
          EXPECT_GT(fired, before) << "never enabled: a transition of " << type.name;
        }
      }
    }
    return fired;
  }

 private:
  std::int64_t draw_int() {
    static constexpr std::int64_t kEnds[] = {std::numeric_limits<std::int64_t>::max(),
                                             std::numeric_limits<std::int64_t>::min()};
    const std::uint64_t pick = random_() % 16;
    if (pick == 0) return kEnds[random_() % 2];
    return static_cast<std::int64_t>(random_() % 12) - 3;
  }
  Val draw_value(bipc::ir::ValueKind kind) {
    if (kind == bipc::ir::ValueKind::Bool) return make_bool(random_() % 2 == 0);
    if (kind == bipc::ir::ValueKind::Float) return make_float(static_cast<double>(draw_int()));
    return make_int(draw_int());
  }
  std::vector<Val> draw_data(const AtomType& type) {
    std::vector<Val> data;
    for (const auto& datum : type.data) data.push_back(draw_value(datum.type.kind));
    return data;
  }

  /// One firing from a random state where the transition is enabled; false when the drawn
  /// state did not enable it (or firing it would break 1-safety).
  bool fire_once(CodeEvaluator& eval, const Layout& layout, bipc::ir::Index a, const AtomType& type,
                 const Transition& transition, bool written_before) {
    std::vector<std::uint8_t> marking(type.places.size(), 0);
    for (bipc::ir::Index p : transition.from) marking[p] = 1;
    std::vector<Val> data = draw_data(type);
    std::vector<ClockState> clocks(type.clocks.size());
    Frame f;
    f.atom_data = data.data();
    f.atom_params = layout.params.data() + layout.atom_params[a];
    f.clocks = clocks.empty() ? nullptr : clocks.data();
    f.clock_units = layout.clock_units.data() + layout.atom_clocks[a];
    if (!transition.guard.empty() && !eval.evaluate(transition.guard, f).b) return false;
    const std::vector<Val> data_before = data;
    const std::vector<std::uint8_t> marking_before = marking;
    if (written_before) data = draw_data(type);  // a connector's `down` wrote the data
    f.atom_data = data.data();
    for (bipc::ir::Index p : transition.from) marking[p] = 0;
    for (bipc::ir::Index p : transition.to) {
      if (marking[p]) return false;
      marking[p] = 1;
    }
    eval.execute(transition.action, f);
    const bool same_data =
        std::memcmp(data.data(), data_before.data(), data.size() * sizeof(Val)) == 0;
    EXPECT_FALSE(same_data && marking == marking_before)
        << "a firing of a transition of " << type.name << " kept its atom's state"
        << (written_before ? " (after a down)" : "");
    return true;
  }

  std::mt19937_64 random_{20261127};
  BoundFunctions functions_;
  std::ostringstream out_;
  StringPool strings_;
  CallContext call_{out_, strings_};
};

TEST_F(StateChangeSemantics, TheRecognisedShapesAlwaysChangeTheState) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kShapes, "Top()");
  ASSERT_TRUE(system);
  // The shapes above: 6 transitions flagged without a down (A->B, the pinned literals, the
  // moves), 4 of them after a down too (A->B, and the two literals other than their pins).
  int flagged = 0;
  for (const Transition& t : system->atom_types.front().transitions) {
    flagged += bipc::ir::always_changes_state(t, false) ? 1 : 0;
  }
  EXPECT_EQ(flagged, 6);
  EXPECT_GT(check_system(*system, 400), 500);
}

TEST_F(StateChangeSemantics, TheBundledModelsTransitionsAlwaysChangeTheirAtoms) {
  for (const char* model : {"models/knuth_yao.bip", "models/tandem.bip"}) {
    const std::optional<bipc::ir::System> system =
        tests::load_model(std::string(SMCBIP_SOURCE_DIR) + "/" + model, "System()");
    ASSERT_TRUE(system) << model;
    EXPECT_GT(check_system(*system, 300), 100) << model;
  }
}

}  // namespace
}  // namespace smcbip::engines
