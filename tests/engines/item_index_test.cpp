// The optimised scheduler's counted items: the Fenwick tree of item counts against a plain
// array, and the items it finds against the list compute_items would have built, along random
// walks of untimed models.
#include "engines/semantics/item_index.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "engines/semantics/runtime.h"
#include "tests/engines/random_model.h"
#include "tests/engines/runtime_instance.h"
#include "tests/engines/temp_model.h"

namespace smcbip::engines {
namespace {

/// Sets random counts and checks every find against a scan of the counts.
void expect_finds_match_scan(std::size_t positions, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  ItemIndex index;
  index.reset(positions);
  std::vector<std::uint32_t> counts(positions, 0);
  for (int round = 0; round < 50; ++round) {
    for (int change = 0; change < 5 && positions > 0; ++change) {
      const std::size_t p = random() % positions;
      counts[p] = static_cast<std::uint32_t>(random() % 4);
      index.set(p, counts[p]);
    }
    std::size_t k = 0;
    for (std::size_t p = 0; p < positions; ++p) {
      for (std::uint32_t rank = 0; rank < counts[p]; ++rank, ++k) {
        ASSERT_EQ(index.find(k), (std::pair<std::size_t, std::uint32_t>{p, rank}))
            << "item " << k << " of " << positions << " positions, round " << round;
      }
    }
    ASSERT_EQ(index.total(), k);
  }
}

TEST(ItemIndex, FindsTheKthItemAsAScanWould) {
  for (std::size_t positions : {0, 1, 2, 3, 7, 8, 9, 64, 100, 1000}) {
    expect_finds_match_scan(positions, positions + 1);
  }
}

TEST(ItemIndex, DecreasingACountMovesLaterItemsBack) {
  ItemIndex index;
  index.reset(3);
  index.set(0, 2);
  index.set(2, 1);
  EXPECT_EQ(index.find(2), (std::pair<std::size_t, std::uint32_t>{2, 0}));
  index.set(0, 1);
  EXPECT_EQ(index.total(), 2u);
  EXPECT_EQ(index.find(1), (std::pair<std::size_t, std::uint32_t>{2, 0}));
}

/// An optimised-scheduler Runtime with everything it refers to.
struct Instance : tests::RuntimeInstance {
  explicit Instance(const bipc::ir::System& system)
      : RuntimeInstance(system, Externs::with_builtins(), options()) {}
  static RuntimeOptions options() {
    RuntimeOptions o;
    o.incremental = true;
    return o;
  }
};

bool same_item(const Item& a, const Item& b) {
  return a.kind == b.kind && a.value == b.value && a.atom == b.atom && a.port == b.port &&
         a.constraint.interval == b.constraint.interval &&
         a.constraint.urgency == b.constraint.urgency && a.offered.interval == b.offered.interval &&
         a.offered.urgency == b.offered.urgency;
}

/// Along a random walk, the items found by item_count and item (asked first, so that they come
/// from the counts) equal those of the list items() builds afterwards.
void expect_counted_items_match_list(const bipc::ir::System& system) {
  Instance instance(system);
  Runtime& runtime = *instance.runtime;
  ASSERT_TRUE(runtime.initialize() && runtime.resume_atoms(0)) << runtime.error().message;
  std::mt19937_64 choose(7);
  for (int step = 0; step < 200; ++step) {
    ASSERT_TRUE(runtime.compute_items()) << runtime.error().message;
    const std::size_t count = runtime.item_count();
    std::vector<Item> found;
    for (std::size_t k = 0; k < count; ++k) found.push_back(runtime.item(k));
    const std::vector<Item>& listed = runtime.items();
    ASSERT_EQ(count, listed.size()) << "step " << step;
    for (std::size_t k = 0; k < count; ++k) {
      ASSERT_TRUE(same_item(found[k], listed[k])) << "step " << step << ", item " << k;
    }
    if (count == 0) return;
    const Item item = listed[choose() % count];
    const TimeValue now = runtime.state().now;
    ASSERT_TRUE(runtime.execute(item, now) && runtime.resume_atoms(now)) << runtime.error().message;
  }
}

TEST(CountedItems, MatchTheListOnRandomUntimedModels) {
  const tests::TempDir dir;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    tests::RandomModelOptions options;
    options.seed = seed;
    options.atoms = 2 + static_cast<int>(seed % 9);
    options.connectors = 1 + static_cast<int>(seed % 7);
    options.priorities = seed % 3 != 0;
    options.hierarchy = seed % 4 != 1;
    const std::string name = "counted_" + std::to_string(seed);
    const std::string text = tests::random_bip_package(options, name);
    SCOPED_TRACE("random model " + std::to_string(seed) + ":\n" + text);
    const std::optional<bipc::ir::System> system =
        tests::load_model(dir.write(name + ".bip", text), "Root()");
    ASSERT_TRUE(system);
    expect_counted_items_match_list(*system);
    if (HasFailure()) return;
  }
}

TEST(CountedItems, MatchTheListOnTheModelFamilies) {
  const std::filesystem::path families =
      std::filesystem::path(SMCBIP_SOURCE_DIR) / "models/families";
  for (const auto& entry : std::filesystem::directory_iterator(families)) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::optional<bipc::ir::System> system = tests::load_model(entry.path(), "Top()");
    ASSERT_TRUE(system);
    expect_counted_items_match_list(*system);
  }
}

// Eager untimed ports make the waiting window the point now: the items are then listed, and an
// eager value that priorities cut to after now is no item although it is enabled (here `alone`
// offering x.p only, below x.p z.p by maximal progress).
const char* const kEagerModel = R"(package eager
  port type P()
  connector type Pair(P a, P b)
    define a b
  end
  connector type Trigger(P a, P b)
    define a' b
  end
  atom type A()
    export port P p()
    port P q()
    place S
    initial to S
    on p from S to S eager
    on q from S to S
  end
  compound type Top()
    component A x(), y(), z()
    connector Pair both(x.p, y.p)
    connector Trigger alone(x.p, z.p)
  end
end
)";

TEST(CountedItems, MatchTheListWithEagerPorts) {
  const std::optional<bipc::ir::System> system = tests::load_model_text(kEagerModel, "Top()");
  ASSERT_TRUE(system);
  expect_counted_items_match_list(*system);
}

}  // namespace
}  // namespace smcbip::engines
