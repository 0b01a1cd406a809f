// The fork-join pool: one published word per fork, claimed in chunks by compare-and-swap.
#include "engines/multithread/fork_join_pool.h"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace smcbip::engines::multithread {

namespace {

/// How long an idle thread spins before it blocks. Simulation steps between two forks take
/// microseconds to tens of microseconds; a futex wake-up costs about as much, so a worker stays
/// awake across a few steps and sleeps when the run is sequential for a while.
constexpr auto kSpinTime = std::chrono::microseconds(200);

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

/// Spins until `done()` holds or kSpinTime has passed; reports which.
template <class Done>
bool spin_until(Done done) {
  const auto deadline = std::chrono::steady_clock::now() + kSpinTime;
  for (unsigned i = 1;; ++i) {
    if (done()) return true;
    relax();
    // Reading the clock costs about as much as a few pauses; look at it now and then only.
    if (i % 64 == 0 && std::chrono::steady_clock::now() >= deadline) return false;
  }
}

constexpr std::uint32_t epoch_of(std::uint64_t word) {
  return static_cast<std::uint32_t>(word >> 32);
}
constexpr std::uint32_t remaining_of(std::uint64_t word) {
  return static_cast<std::uint32_t>(word);
}

}  // namespace

ForkJoinPool::ForkJoinPool(unsigned threads) {
  for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this, t] { work(t); });
}

ForkJoinPool::~ForkJoinPool() {
  {
    std::lock_guard lock(mutex_);
    stop_.store(true);
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ForkJoinPool::run_erased(std::size_t count, Erased fn, void* task) {
  if (count == 0) return;
  if (workers_.empty() || count == 1 || count > 0x7FFFFFFFu) {
    for (std::size_t i = 0; i < count; ++i) fn(task, i, 0);
    return;
  }
  fn_ = fn;
  task_ = task;
  count_ = count;
  // A few chunks per thread balance uneven tasks without a compare-and-swap per tiny task.
  chunk_.store(std::max<std::size_t>(1, count / (4 * size())), std::memory_order_relaxed);
  completed_.store(0, std::memory_order_relaxed);
  epoch_ = epoch_ == 0xFFFFFFFFu ? 1 : epoch_ + 1;
  // Sequentially consistent with the sleepers_ load below and the workers' increment of it
  // before they re-check the word: either they see this fork or this fork sees them asleep.
  work_.store(std::uint64_t{epoch_} << 32 | count);
  if (sleepers_.load() > 0) {
    { std::lock_guard lock(mutex_); }
    wake_.notify_all();
  }
  drain(epoch_, 0);
  auto finished = [&] { return completed_.load(std::memory_order_acquire) == count; };
  if (spin_until(finished)) return;
  std::unique_lock lock(mutex_);
  joiner_waiting_.store(true);
  done_.wait(lock, [&] { return completed_.load() == count; });
  joiner_waiting_.store(false);
}

void ForkJoinPool::drain(std::uint32_t epoch, unsigned thread) {
  std::uint64_t word = work_.load(std::memory_order_acquire);
  for (;;) {
    if (epoch_of(word) != epoch || remaining_of(word) == 0) return;
    // While this fork has unclaimed tasks it cannot end, so chunk_ is still this fork's when
    // the exchange below succeeds; a later fork's value only ever meets a failing exchange.
    const auto chunk = static_cast<std::uint32_t>(
        std::min<std::size_t>(chunk_.load(std::memory_order_relaxed), remaining_of(word)));
    if (!work_.compare_exchange_weak(word, word - chunk, std::memory_order_acq_rel,
                                     std::memory_order_acquire)) {
      continue;
    }
    // Claimed: the fork's fields stay put until these tasks are counted as completed.
    const std::size_t count = count_;
    const std::size_t first = count - remaining_of(word);
    for (std::size_t i = first; i < first + chunk; ++i) fn_(task_, i, thread);
    if (completed_.fetch_add(chunk, std::memory_order_acq_rel) + chunk == count &&
        joiner_waiting_.load()) {
      { std::lock_guard lock(mutex_); }
      done_.notify_one();
    }
    word = work_.load(std::memory_order_acquire);
  }
}

void ForkJoinPool::work(unsigned thread) {
  std::uint32_t seen = 0;
  for (;;) {
    auto published = [&] {
      return stop_.load(std::memory_order_relaxed) ||
             epoch_of(work_.load(std::memory_order_acquire)) != seen;
    };
    if (!spin_until(published)) {
      std::unique_lock lock(mutex_);
      sleepers_.fetch_add(1);
      wake_.wait(lock, [&] { return stop_.load() || epoch_of(work_.load()) != seen; });
      sleepers_.fetch_sub(1);
    }
    if (stop_.load()) return;
    seen = epoch_of(work_.load(std::memory_order_acquire));
    drain(seen, thread);
  }
}

}  // namespace smcbip::engines::multithread
