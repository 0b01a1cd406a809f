// smc::OrderedSampler: outcomes reach the consumer in run-index order whatever thread made them
// and however long each run took, the consumer stops where it says, and a run's exception is
// rethrown at its turn; the thread that consumes makes runs too.
#include "smc/check/ordered_sampler.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace smcbip::smc {
namespace {

/// A run's index, with a delay that varies so that later runs often finish first.
void slow_run(std::uint64_t index, std::uint64_t& outcome) {
  if (index % 7 == 3) std::this_thread::sleep_for(std::chrono::microseconds(200));
  outcome = index * index;
}

TEST(OrderedSampler, ConsumesInRunIndexOrder) {
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    OrderedSampler<std::uint64_t> sampler(
        threads, [](unsigned, std::uint64_t i, std::uint64_t& out) { slow_run(i, out); }, 32);
    std::vector<std::uint64_t> seen;
    const std::uint64_t end = sampler.run(5, [&](const std::uint64_t& outcome) {
      seen.push_back(outcome);
      return seen.size() < 1000;
    });
    EXPECT_EQ(end, 1005u) << threads;
    ASSERT_EQ(seen.size(), 1000u);
    for (std::uint64_t k = 0; k < seen.size(); ++k) {
      ASSERT_EQ(seen[k], (k + 5) * (k + 5)) << threads << " threads, run " << k + 5;
    }
  }
}

TEST(OrderedSampler, CanRunAgainAfterStopping) {
  OrderedSampler<std::uint64_t> sampler(
      2, [](unsigned, std::uint64_t i, std::uint64_t& out) { slow_run(i, out); }, 16);
  for (int round = 0; round < 3; ++round) {
    std::uint64_t expected = 0, taken = 0;
    sampler.run(0, [&](const std::uint64_t& outcome) {
      EXPECT_EQ(outcome, expected * expected);
      ++expected;
      return ++taken < 100;
    });
    EXPECT_EQ(taken, 100u);
  }
}

TEST(OrderedSampler, RethrowsARunsExceptionAtItsTurn) {
  for (const unsigned threads : {1u, 2u}) {
    OrderedSampler<std::uint64_t> sampler(threads,
                                          [](unsigned, std::uint64_t i, std::uint64_t& out) {
                                            if (i == 40) throw std::runtime_error("run 40");
                                            out = i;
                                          });
    std::uint64_t consumed = 0;
    EXPECT_THROW(sampler.run(0,
                             [&](const std::uint64_t& outcome) {
                               EXPECT_EQ(outcome, consumed);
                               ++consumed;
                               return true;
                             }),
                 std::runtime_error);
    EXPECT_EQ(consumed, 40u) << threads;
  }
}

TEST(OrderedSampler, TheCallingThreadIsWorkerZero) {
  // No thread of its own for the consumer: with 2 threads, the caller and one helper make runs.
  // The helper waits until the caller has made a run: otherwise a fast helper may make every run
  // while the caller only consumes, and whether the caller makes one depends on the scheduler.
  const std::thread::id caller = std::this_thread::get_id();
  std::mutex mutex;
  std::condition_variable caller_made_one;
  std::set<std::thread::id> makers;
  bool zero_elsewhere = false;
  OrderedSampler<std::uint64_t> sampler(2, [&](unsigned w, std::uint64_t i, std::uint64_t& out) {
    std::unique_lock lock(mutex);
    const bool on_caller = std::this_thread::get_id() == caller;
    makers.insert(std::this_thread::get_id());
    zero_elsewhere = zero_elsewhere || (w == 0) != on_caller;
    if (on_caller)
      caller_made_one.notify_all();
    else
      caller_made_one.wait(lock, [&] { return makers.contains(caller); });
    out = i;
  });
  std::uint64_t expected = 0;
  sampler.run(0, [&](const std::uint64_t& outcome) {
    EXPECT_EQ(outcome, expected++);
    return expected < 2000;
  });
  EXPECT_FALSE(zero_elsewhere);
  EXPECT_LE(makers.size(), 2u);
  EXPECT_TRUE(makers.contains(caller));
}

}  // namespace
}  // namespace smcbip::smc
