// always_changes_state says "always changes" only where no value of the atom's data can make
// the firing keep its places and data: each transition below is lowered from BIP text and the
// answer checked, for the shapes it recognises and for near misses it must not.
#include "bipc/ir/state_change.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/bipc/lower_test_util.h"

namespace smcbip::bipc::ir {
namespace {

/// The first transition of an atom type with data `n`, `m`, places A and B, whose transition is
/// `transition` (written in BIP after the places).
class StateChangeTest : public ::testing::Test {
 protected:
  bool changes(const std::string& transition, bool written_before = false) {
    const std::string text =
        "package p\n"
        "  port type Sig()\n"
        "  atom type T()\n"
        "    data int n, m\n"
        "    clock x unit millisecond\n"
        "    port Sig go()\n"
        "    place A, B\n"
        "    initial to A do { n = 0; m = 0; }\n"
        "    " +
        transition +
        "\n"
        "  end\n"
        "  compound type S()\n"
        "    component T t()\n"
        "  end\n"
        "end\n";
    lowered_ = lower_test::lower_ok(text, "S()");
    if (!lowered_->system) return false;
    const AtomType& type = lowered_->system->atom_types.front();
    EXPECT_EQ(type.transitions.size(), 1u);
    return always_changes_state(type.transitions.front(), written_before);
  }

 private:
  std::unique_ptr<lower_test::Lowered> lowered_;
};

TEST_F(StateChangeTest, APlaceLeftForAnotherAlwaysChanges) {
  EXPECT_TRUE(changes("on go from A to B"));
  EXPECT_TRUE(changes("on go from A to B", true));
  EXPECT_FALSE(changes("on go from A to A"));
}

TEST_F(StateChangeTest, ADatumMovedByANonZeroLiteralAlwaysChanges) {
  EXPECT_TRUE(changes("on go from A to A do { n = n + 1; }"));
  EXPECT_TRUE(changes("on go from A to A do { n = n - 3; x = 0; }"));
  EXPECT_TRUE(changes("on go from A to A do { n = n + 1; n = n + 1; }"));
  // A connector's `down` may have moved n the other way first.
  EXPECT_FALSE(changes("on go from A to A do { n = n + 1; }", true));
}

TEST_F(StateChangeTest, MovesThatCancelOrComeFromElsewhereMayKeep) {
  EXPECT_FALSE(changes("on go from A to A do { n = n + 1; n = n - 1; }"));
  EXPECT_FALSE(changes("on go from A to A do { n = n + 0; }"));
  EXPECT_FALSE(changes("on go from A to A do { n = m + 1; }"));
}

TEST_F(StateChangeTest, AMoveThroughAnotherDatumIsFollowed) {
  EXPECT_TRUE(changes("on go from A to A do { m = n + 2; n = m - 1; }"));
  EXPECT_FALSE(changes("on go from A to A do { m = n + 2; n = m - 2; }"));
}

TEST_F(StateChangeTest, ALiteralOtherThanTheOneTheGuardPinsAlwaysChanges) {
  EXPECT_TRUE(changes("on go from A to A provided (n == 0) do { n = 1; }"));
  EXPECT_TRUE(changes("on go from A to A provided (m > 0 && 2 == n) do { n = 1; }"));
  // Whatever `down` wrote, n ends at 1 and was 0 before the step.
  EXPECT_TRUE(changes("on go from A to A provided (n == 0) do { n = 1; }", true));
}

TEST_F(StateChangeTest, ALiteralTheGuardDoesNotPinOtherwiseMayKeep) {
  EXPECT_FALSE(changes("on go from A to A provided (n == 1) do { n = 1; }"));
  EXPECT_FALSE(changes("on go from A to A provided (n != 0) do { n = 1; }"));
  EXPECT_FALSE(changes("on go from A to A provided (m == 0) do { n = 1; }"));
  EXPECT_FALSE(changes("on go from A to A provided (n == 0 || m == 0) do { n = 1; }"));
  EXPECT_FALSE(changes("on go from A to A do { n = 1; }"));
}

TEST_F(StateChangeTest, ActionsOfOtherShapesMayKeep) {
  EXPECT_FALSE(changes("on go from A to A provided (n == 0) do { if (m > 0) then n = 1; fi }"));
  EXPECT_FALSE(changes("on go from A to A do { n = n * 2 + 1; }"));
  EXPECT_FALSE(changes("on go from A to A"));
}

}  // namespace
}  // namespace smcbip::bipc::ir
