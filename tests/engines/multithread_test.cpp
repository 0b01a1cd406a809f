// The multithread scheduler against the reference semantics: its runs visit only reachable
// states, its traces equal the reference engine's on the same seed, its errors are the first
// failing atom's in port order; and the fork-join pool and the parallel-safety scan it rests on.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

#include "bipc/bipc.h"
#include "conformance_externs.h"
#include "engines/engines.h"
#include "engines/explore.h"
#include "engines/multithread/fork_join_pool.h"
#include "engines/multithread/pool_firing.h"
#include "engines/semantics/runtime.h"
#include "random_model.h"
#include "runtime_instance.h"
#include "trace_oracles.h"

namespace smcbip::tests {
namespace {

namespace fs = std::filesystem;

/// A model of the tests, by file and root.
struct ModelFile {
  fs::path file;
  std::string root;
};

/// Untimed conformance models whose interactions join several atoms (the parallel path); with
/// `random_data`, also those whose actions draw rand(), whose states depend on the random stream
/// and so are not those of an exploration.
std::vector<ModelFile> conformance_models(bool random_data) {
  const fs::path dir = conformance_dir();
  std::vector<ModelFile> models = {
      {dir / "running/broadcast.bip", "MyCompoundType()"},
      {dir / "running/broadcast_up_down.bip", "MyCompoundType()"},
      {dir / "running/rendezvous_down.bip", "MyCompoundType()"},
      {dir / "running/nested2.bip", "MyCompoundType()"},
      {dir / "running/maximal_progress.bip", "Top()"},
      {dir / "running/dining_philo.bip", "DiningPhilo()"},
      {dir / "running/priority_rules_atom.bip", "MyCompoundType()"},
      {dir / "running/multi_export_compound.bip", "Top()"},
      {dir / "running_multithread_extra/conflicting.bip", "Comp()"},
      {dir / "running_multithread_extra/non_conflicting.bip", "Comp()"}};
  if (random_data) models.push_back({dir / "running/hierarchical.bip", "MyCompoundType()"});
  return models;
}

std::vector<ModelFile> family_models() {
  const fs::path dir = fs::path(SMCBIP_SOURCE_DIR) / "models/families";
  std::vector<ModelFile> models;
  for (const char* name :
       {"rendezvous_10", "broadcast_10", "chain_10", "priorities_10", "work_10"}) {
    models.push_back({dir / (std::string(name) + ".bip"), "Top()"});
  }
  return models;
}

/// Random untimed packages (timed ones with `clocks`), written to a temporary folder.
std::vector<ModelFile> random_models(bool clocks) {
  const fs::path dir = fs::temp_directory_path() / "smcbip_multithread_test";
  fs::create_directories(dir);
  std::vector<ModelFile> models;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    RandomModelOptions options;
    options.seed = seed;
    options.atoms = 3 + static_cast<int>(seed % 5);
    options.connectors = 2 + static_cast<int>(seed % 4);
    options.clocks = clocks;
    options.hierarchy = seed % 3 != 0;
    const std::string name =
        std::string("mt_random_") + (clocks ? "timed_" : "") + std::to_string(seed);
    const fs::path file = dir / (name + ".bip");
    std::ofstream(file) << random_bip_package(options, name);
    models.push_back({file, "Root()"});
  }
  return models;
}

std::optional<bipc::ir::System> load(const ModelFile& model) {
  bipc::FrontendOptions options;
  options.file = model.file.string();
  options.include_dirs = {model.file.parent_path().string()};
  options.root = model.root;
  bipc::FrontendResult result = bipc::run_frontend(options, true);
  if (!result.system || result.diags.has_errors()) {
    ADD_FAILURE() << "front end rejected " << model.file << ":\n"
                  << result.diags.format(result.model.files);
    return std::nullopt;
  }
  return std::move(result.system);
}

engines::Externs test_externs() {
  engines::Externs externs = engines::Externs::with_builtins();
  register_conformance_externs(externs);
  return externs;
}

/// A Runtime with everything it refers to.
struct Instance : RuntimeInstance {
  Instance(const bipc::ir::System& system, const engines::Externs& externs, unsigned threads)
      : RuntimeInstance(system, externs, options(threads)) {}
  static engines::RuntimeOptions options(unsigned threads) {
    engines::RuntimeOptions o;
    o.threads = threads;
    if (threads > 1) o.parallel_firing = engines::make_pool_firing;
    o.parallel_min_work = 0;  // fork even for cheap atoms: the path under test
    return o;
  }
};

constexpr std::uint64_t kSteps = 12;

/// Random walks of the multithread scheduler stay inside the states the reference exploration
/// reaches in as many steps.
void expect_reachable_walks(const ModelFile& model) {
  SCOPED_TRACE(model.file.string());
  const std::optional<bipc::ir::System> system = load(model);
  if (!system) return;
  const engines::Externs externs = test_externs();
  Instance reference(*system, externs, 1);
  ASSERT_TRUE(reference.runtime->initialize() && reference.runtime->resume_atoms(0));
  const std::unordered_set<std::string> reachable =
      engines::reachable_state_keys(*reference.runtime, kSteps);
  for (unsigned threads : {2u, 4u}) {
    Instance walker(*system, externs, threads);
    engines::Runtime& runtime = *walker.runtime;
    ASSERT_TRUE(runtime.initialize() && runtime.resume_atoms(0));
    const engines::RunState initial = runtime.state();
    for (std::uint64_t walk = 0; walk < 4; ++walk) {
      std::mt19937_64 choose(walk);
      ASSERT_TRUE(runtime.restore(initial));
      for (std::uint64_t step = 0; step < kSteps; ++step) {
        if (!runtime.compute_items() || runtime.items().empty()) break;
        const auto& items = runtime.items();
        const engines::Item item = items[choose() % items.size()];
        const engines::TimeValue now = runtime.state().now;
        if (!runtime.execute(item, now) || !runtime.resume_atoms(now)) break;
        ASSERT_TRUE(reachable.count(engines::state_key(runtime.state())))
            << "threads " << threads << ", walk " << walk << ", step " << step + 1
            << ": a state the reference exploration does not reach";
      }
    }
  }
}

TEST(MultithreadReachable, ConformanceModels) {
  if (!fs::exists(conformance_dir())) GTEST_SKIP() << "shared conformance data not found";
  for (const ModelFile& model : conformance_models(false)) expect_reachable_walks(model);
}

TEST(MultithreadReachable, Families) {
  for (const ModelFile& model : family_models()) expect_reachable_walks(model);
}

TEST(MultithreadReachable, RandomModels) {
  for (const ModelFile& model : random_models(false)) expect_reachable_walks(model);
}

std::string trace(const bipc::ir::System& system, engines::EngineKind engine, unsigned threads,
                  std::uint64_t seed) {
  engines::SimulateOptions options;
  options.engine = engine;
  options.threads = threads;
  options.parallel_min_work = 0;  // fork even for cheap atoms: the path under test
  options.seed = seed;
  options.limit = 150;
  std::ostringstream out;
  engines::simulate(system, options, test_externs(), out);
  return std::move(out).str();
}

/// Same seed, same text: the multithread engine on 2 and 4 threads against the reference.
void expect_same_traces(const ModelFile& model) {
  SCOPED_TRACE(model.file.string());
  const std::optional<bipc::ir::System> system = load(model);
  if (!system) return;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Lines expected = split_lines(trace(*system, engines::EngineKind::Reference, 1, seed));
    for (unsigned threads : {2u, 4u}) {
      const Lines actual =
          split_lines(trace(*system, engines::EngineKind::Multithread, threads, seed));
      EXPECT_EQ(describe_difference(actual, expected), "")
          << "seed " << seed << ", threads " << threads;
    }
  }
}

TEST(MultithreadTraces, ConformanceModels) {
  if (!fs::exists(conformance_dir())) GTEST_SKIP() << "shared conformance data not found";
  for (const ModelFile& model : conformance_models(true)) expect_same_traces(model);
}

TEST(MultithreadTraces, Families) {
  for (const ModelFile& model : family_models()) expect_same_traces(model);
}

TEST(MultithreadTraces, RandomModels) {
  for (const ModelFile& model : random_models(false)) expect_same_traces(model);
  for (const ModelFile& model : random_models(true)) expect_same_traces(model);
}

/// Writes `text` as package `name` and loads root `root`.
std::optional<bipc::ir::System> load_text(const std::string& name, const std::string& text,
                                          const std::string& root) {
  const fs::path dir = fs::temp_directory_path() / "smcbip_multithread_test";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".bip");
  std::ofstream(file) << text;
  return load({file, root});
}

// Both atoms of the rendezvous break their invariant in the same step: the reference engine
// stops at the first one in port order, and so must the parallel firing.
TEST(MultithreadErrors, FirstFailingAtomInPortOrder) {
  const std::optional<bipc::ir::System> system = load_text("mt_two_failures", R"(
package mt_two_failures
  port type P()
  connector type Pair(P a, P b)
    define a b
  end
  atom type A(int limit)
    data int n
    export port P go()
    place S
    initial to S do { n = 0; }
    on go from S to S do { n = n + 1; }
    invariant small at S provided (n < limit)
  end
  compound type Top()
    component A second(3)
    component A first(3)
    connector Pair c(second.go, first.go)
  end
end
)",
                                                           "Top()");
  ASSERT_TRUE(system);
  const std::string expected = trace(*system, engines::EngineKind::Reference, 1, 1);
  EXPECT_NE(expected.find("the invariant small of component second has been violated"),
            std::string::npos)
      << expected;
  EXPECT_EQ(trace(*system, engines::EngineKind::Multithread, 2, 1), expected);
  EXPECT_EQ(trace(*system, engines::EngineKind::Multithread, 4, 1), expected);
}

TEST(MultithreadSafety, PrintfAndRandAreNotParallelSafeMinIs) {
  const std::optional<bipc::ir::System> system = load_text("mt_safety", R"(
package mt_safety
  extern function printf(string, int)
  extern function int rand()
  extern function int min(int, int)
  port type P()
  atom type Pure()
    data int n
    export port P go()
    place S
    initial to S do { n = 0; }
    on go from S to S provided (n < 5) do { n = min(n + 1, 4); }
  end
  atom type Prints()
    data int n
    export port P go()
    place S
    initial to S
    on go from S to S do { printf("%d\n", n); }
  end
  atom type Draws()
    data int n
    export port P go()
    place S, T
    initial to S
    on go from S to T do { n = rand(); }
    internal from T to S provided (n >= 0)
  end
  connector type Three(P a, P b, P c)
    define a b c
  end
  compound type Top()
    component Pure p()
    component Prints q()
    component Draws r()
    connector Three all(p.go, q.go, r.go)
  end
end
)",
                                                           "Top()");
  ASSERT_TRUE(system);
  engines::Externs externs = engines::Externs::with_builtins();
  engines::StringPool strings;
  engines::BoundFunctions functions;
  engines::bind_functions(*system, externs, strings, functions);
  const std::vector<std::uint8_t> safe = engines::parallel_safe_atom_types(*system, functions);
  ASSERT_EQ(safe.size(), system->atom_types.size());
  for (std::size_t t = 0; t < safe.size(); ++t) {
    const bool pure = system->atom_types[t].name == "mt_safety.Pure";
    EXPECT_EQ(safe[t] != 0, pure) << system->atom_types[t].name;
  }
}

TEST(ForkJoinPool, RunsEveryTaskOnceInEveryFork) {
  for (unsigned threads : {1u, 2u, 4u}) {
    engines::multithread::ForkJoinPool pool(threads);
    ASSERT_EQ(pool.size(), threads);
    for (std::size_t count : {0u, 1u, 2u, 3u, 17u, 1000u}) {
      for (int fork = 0; fork < 50; ++fork) {
        std::vector<std::atomic<int>> runs(count);
        std::atomic<bool> thread_in_range{true};
        auto task = [&](std::size_t i, unsigned thread) {
          runs[i].fetch_add(1);
          if (thread >= threads) thread_in_range = false;
        };
        pool.run(count, task);
        for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << i;
        EXPECT_TRUE(thread_in_range);
      }
    }
  }
}

}  // namespace
}  // namespace smcbip::tests
