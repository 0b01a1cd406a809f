// No allocation in the steps of a started Execution (engines/api/execution.h): this executable
// replaces the global operator new and delete with counting ones, and counts only inside the
// calls under test (step, run_until, read, write, feed), once a warm-up let the buffers grow.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <optional>
#include <sstream>
#include <string>

#include "engines/api/execution.h"
#include "engines/engines.h"
#include "tests/engines/generated_conformance.h"
#include "tests/engines/temp_model.h"
#include "tests/engines/trace_oracles.h"

namespace {

std::atomic<bool> counting{false};
std::atomic<std::uint64_t> allocations{0};

void* allocate(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* allocate_aligned(std::size_t size, std::align_val_t align) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  const auto alignment = static_cast<std::size_t>(align);
  const std::size_t rounded = (size + alignment - 1) / alignment * alignment;
  if (void* p = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, std::align_val_t align) {
  return allocate_aligned(size, align);
}
void* operator new[](std::size_t size, std::align_val_t align) {
  return allocate_aligned(size, align);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace smcbip::tests {
namespace {

using engines::Execution;
using engines::StepOutcome;

/// The allocations made by `call()`.
template <class Call>
std::uint64_t allocations_in(Call call) {
  const std::uint64_t before = allocations.load();
  counting = true;
  call();
  counting = false;
  return allocations.load() - before;
}

/// What allocations_in_steps counted.
struct Counts {
  std::uint64_t allocations = 0;
  std::uint64_t steps = 0;  // executed
};

/// Calls step() `calls` times (or run_until over slices of `slice` when positive), starting a
/// new run (not counted) whenever one ends.
Counts allocations_in_steps(Execution& execution, std::uint64_t calls,
                            engines::TimeValue slice = 0) {
  Counts counts;
  std::uint64_t run = 0;
  engines::TimeValue until = execution.now();
  std::uint64_t steps_before = execution.steps();
  for (std::uint64_t call = 0; call < calls; ++call) {
    StepOutcome outcome;
    if (slice > 0) {
      until += slice;
      counts.allocations += allocations_in([&] { outcome = execution.run_until(until); });
    } else {
      counts.allocations += allocations_in([&] { outcome = execution.step(); });
    }
    counts.steps += execution.steps() - steps_before;
    steps_before = execution.steps();
    if (!outcome.ended) continue;
    EXPECT_NE(outcome.end, engines::RunEnd::Error) << outcome.message;
    if (outcome.end == engines::RunEnd::Error || !execution.start(++run)) return counts;
    until = execution.now();
    steps_before = 0;
  }
  return counts;
}

template <class Engine>
class ExecutionAllocations : public ::testing::Test {
 protected:
  static engines::SimulateOptions options() {
    engines::SimulateOptions result;
    result.engine = Engine::kind;
    result.seed = 1;
    return result;
  }

  /// The model `file` of models/ with `root`, warmed up, then `steps` steps counted.
  void expect_no_allocation(const char* file, const char* root, engines::TimeValue slice = 0) {
    const std::optional<bipc::ir::System> system =
        load_model(std::filesystem::path(SMCBIP_SOURCE_DIR) / "models" / file, root);
    ASSERT_TRUE(system);
    std::ostringstream out;
    const engines::Externs externs = engines::Externs::with_builtins();
    Execution execution(*system, options(), externs, out);
    ASSERT_EQ(execution.problem(), "");
    ASSERT_TRUE(execution.start());
    allocations_in_steps(execution, 3000, slice);  // warm-up: the buffers grow
    const Counts counts = allocations_in_steps(execution, 5000, slice);
    EXPECT_EQ(counts.allocations, 0u);
    // Most calls step (some find the end of a run).
    EXPECT_GT(counts.steps, 2500u);
  }
};

using Engines = ::testing::Types<Reference, Optimised>;
TYPED_TEST_SUITE(ExecutionAllocations, Engines, EngineNames);

TEST(CountingAllocator, CountsWhatItShould) {
  int* p = nullptr;
  EXPECT_EQ(allocations_in([&] { p = new int(1); }), 1u);
  delete p;
  std::string* text = nullptr;  // the object and its buffer
  EXPECT_EQ(allocations_in([&] { text = new std::string(100, 'x'); }), 2u);
  delete text;
}

TYPED_TEST(ExecutionAllocations, StochasticChannel) {
  this->expect_no_allocation("channel.bip", "System()");
}

TYPED_TEST(ExecutionAllocations, StochasticChannelInSlices) {
  this->expect_no_allocation("channel.bip", "System()", 3'000'000);
}

TYPED_TEST(ExecutionAllocations, UntimedRendezvous) {
  this->expect_no_allocation("families/rendezvous_10.bip", "Top()");
}

TYPED_TEST(ExecutionAllocations, UntimedPriorityChain) {
  this->expect_no_allocation("families/priorities_10.bip", "Top()");
}

TYPED_TEST(ExecutionAllocations, TimedRoverWithPriorities) {
  this->expect_no_allocation("rover_watchdog.bip", "RoverSystem()");
}

TYPED_TEST(ExecutionAllocations, StochasticRace) {
  this->expect_no_allocation("two_exponentials.bip", "System()");
}

// A sensor fed by the host passes its readings to a filter, which takes them only while the
// host enables it, then reports low or high, an atom priority rule preferring high.
constexpr const char* kHostModel = R"(package host
  port type Int(int v)
  port type Sig()
  connector type Pass(Int src, Int dst)
    define src dst
    on src dst down { dst.v = src.v; }
  end
  connector type Solo(Sig p)
    define p
  end
  atom type Sensor()
    data int v
    extern port Int reading(v) as "Host" remember
    export port Int out(v)
    place IDLE, FULL
    initial to IDLE do { v = 0; }
    on reading from IDLE to FULL
    on out from FULL to IDLE
  end
  atom type Filter()
    data int v, sum, enabled
    export port Int in(v)
    export port Sig low(), high()
    place READY, TOOK
    initial to READY do { v = 0; sum = 0; enabled = 1; }
    on in from READY to TOOK provided (enabled == 1) do { sum = sum + v; }
    on low from TOOK to READY
    on high from TOOK to READY provided (sum % 2 == 0)
    priority prefer_high low < high provided (sum > 0)
  end
  compound type Top()
    component Sensor s()
    component Filter f()
    connector Pass pass(s.out, f.in)
    connector Solo low(f.low)
    connector Solo high(f.high)
  end
end
)";

// The C++ that bipc gen generated for conformance models (CompiledModel), as flight software
// embeds it: timed, with compound and atom priorities, with builtin extern calls. Their runs are
// short: new runs start over and over.
TYPED_TEST(ExecutionAllocations, GeneratedConformanceModels) {
  if (!std::filesystem::exists(conformance_dir())) {
    GTEST_SKIP() << "shared conformance data not found (set SMCBIP_SHARED_DATA)";
  }
  if (generated_conformance_models().empty()) {
    GTEST_SKIP() << "no conformance model was generated (shared data absent at build time)";
  }
  const std::pair<const char*, const char*> cases[] = {
      {"running/clock_speed", "Compound()"},
      {"running/hierarch_priority", "MyCompoundType()"},
      {"running/priority_rules_atom", "MyCompoundType()"},
  };
  const engines::Externs externs = engines::Externs::with_builtins();
  for (const auto& [model, root] : cases) {
    SCOPED_TRACE(model);
    const std::optional<bipc::ir::System> system = load_conformance_model(model, root);
    ASSERT_TRUE(system);
    const engines::CompiledModel::CodeFactory factory = find_generated_conformance(model, root);
    ASSERT_NE(factory, nullptr);
    const engines::CompiledModel compiled(*system, factory);
    std::ostringstream out;
    Execution execution(compiled, TestFixture::options(), externs, out);
    ASSERT_TRUE(execution.start());
    allocations_in_steps(execution, 3000);
    const Counts counts = allocations_in_steps(execution, 5000);
    EXPECT_EQ(counts.allocations, 0u);
    EXPECT_GT(counts.steps, 0u);
  }
}

TYPED_TEST(ExecutionAllocations, HostWritesReadsAndFeeds) {
  const std::optional<bipc::ir::System> system = load_model_text(kHostModel, "Top()");
  ASSERT_TRUE(system);
  std::ostringstream out;
  const engines::Externs externs = engines::Externs::with_builtins();
  Execution execution(*system, TestFixture::options(), externs, out);
  ASSERT_EQ(execution.problem(), "");
  const std::optional<engines::AtomPort> reading = execution.find_port("ROOT.s", "reading");
  const std::optional<engines::DataSlot> enabled = execution.find_data("ROOT.f", "enabled");
  const std::optional<engines::DataSlot> sum = execution.find_data("ROOT.f", "sum");
  ASSERT_TRUE(reading && enabled && sum);
  ASSERT_TRUE(execution.start());
  std::uint64_t counted = 0;
  std::int64_t total = 0;
  for (int round = 0; round < 2000; ++round) {
    const engines::TimeValue t = (round + 1) * 1'000'000;
    const engines::Val value[] = {engines::make_int(round % 7)};
    std::uint64_t made = allocations_in([&] {
      execution.feed(reading->atom, reading->port, t, value);
      execution.write(enabled->atom, enabled->slot, engines::make_int(round % 3 == 0 ? 0 : 1));
      execution.run_until(t + 500'000);
      total = execution.read(sum->atom, sum->slot).i;
    });
    if (round >= 100) counted += made;  // warm-up: the first rounds
  }
  EXPECT_EQ(counted, 0u);
  EXPECT_GT(total, 0);
  EXPECT_GT(execution.steps(), 2000u);
}

}  // namespace
}  // namespace smcbip::tests
