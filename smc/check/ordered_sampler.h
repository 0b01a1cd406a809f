// Runs produced on several threads and consumed in run-index order, as if one thread had made
// them: a sequential test then sees the same outcomes, and stops at the same run, whatever
// thread finished first (Younes 2005, unbiased parallel sampling).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace smcbip::smc {

template <class Outcome>
class OrderedSampler {
 public:
  /// `produce(worker, index, outcome)` makes run `index` on thread `worker` (0..threads-1) into
  /// `outcome`, which holds an earlier outcome (so that its storage is reused); each worker
  /// uses its own state. Worker 0 is the thread that calls run(). Workers run at most about
  /// `ahead` runs past the one consumed last.
  OrderedSampler(unsigned threads, std::function<void(unsigned, std::uint64_t, Outcome&)> produce,
                 std::uint64_t ahead = 256)
      : threads_(threads == 0 ? 1 : threads),
        produce_(std::move(produce)),
        ring_((ahead / kBatch + 2) * kBatch) {}

  /// Calls `consume` with the outcomes of runs first, first + 1, ... until it returns false;
  /// returns the index after the last consumed. An exception a run threw is rethrown when its
  /// turn comes.
  std::uint64_t run(std::uint64_t first, const std::function<bool(const Outcome&)>& consume) {
    if (threads_ == 1) {
      Outcome& outcome = ring_.front().outcome;
      std::uint64_t i = first;
      do {
        produce_(0, i++, outcome);
      } while (consume(outcome));
      return i;
    }
    next_ = consumed_ = first;
    stop_ = consumer_waits_ = false;
    idle_helpers_ = 0;
    for (Slot& slot : ring_) slot.ready = false;
    std::vector<std::thread> helpers;
    try {
      for (unsigned w = 1; w < threads_; ++w) helpers.emplace_back([this, w] { help(w); });
      const std::uint64_t end = consume_in_order(first, consume);
      stop(helpers);
      return end;
    } catch (...) {
      stop(helpers);
      throw;
    }
  }

 private:
  // Runs are claimed and handed over in batches: one lock per batch, not per run (short runs
  // would otherwise spend their time waiting for the lock).
  static constexpr std::uint64_t kBatch = 16;

  // A slot per cache line or more: the outcomes of two batches, made on two threads, then never
  // share one.
  struct alignas(64) Slot {
    Outcome outcome{};
    std::exception_ptr error;
    bool ready = false;
  };

  Slot& slot(std::uint64_t index) { return ring_[index % ring_.size()]; }

  /// Whether a batch more can be claimed without overwriting outcomes not consumed yet.
  bool has_room() const { return next_ + kBatch <= consumed_ + ring_.size(); }

  /// Claims the next batch (under the lock); returns its first run.
  std::uint64_t claim() {
    const std::uint64_t first = next_;
    next_ += kBatch;
    return first;
  }

  /// Makes the runs of the batch from `first` into their slots, which are this worker's alone
  /// until it marks them ready; a run's exception waits in its slot for its turn.
  void produce_batch(unsigned worker, std::uint64_t first) {
    for (std::uint64_t k = 0; k < kBatch; ++k) {
      Slot& s = slot(first + k);
      s.error = nullptr;
      try {
        produce_(worker, first + k, s.outcome);
      } catch (...) {
        s.error = std::current_exception();
      }
    }
  }

  /// Hands the batch from `first` over to the consumer (under the lock).
  void mark_ready(std::uint64_t first) {
    for (std::uint64_t k = 0; k < kBatch; ++k) slot(first + k).ready = true;
  }

  // The calling thread consumes and, while the next outcome is not ready, makes runs itself: a
  // consumer on a thread of its own would sleep and be woken for each batch, and that context
  // switch takes from the workers a time that short runs cannot spare.
  std::uint64_t consume_in_order(std::uint64_t i,
                                 const std::function<bool(const Outcome&)>& consume) {
    for (;;) {
      const std::uint64_t ready = await_ready(i);
      // The slots stay the consumer's until consumed_ passes them: read in place.
      for (std::uint64_t k = 0; k < ready; ++k) {
        Slot& s = slot(i + k);
        if (s.error) std::rethrow_exception(s.error);
        if (!consume(s.outcome)) return i + k + 1;
      }
      bool wake;
      {
        std::lock_guard lock(mutex_);
        for (std::uint64_t k = 0; k < ready; ++k) slot(i + k).ready = false;
        consumed_ = i += ready;
        wake = idle_helpers_ > 0;
      }
      if (wake) room_.notify_all();
    }
  }

  /// How many outcomes from run `i` on are ready, at least one. Until one is, the caller makes
  /// batches as worker 0 while the ring has room, and otherwise waits for the helper making
  /// run `i`.
  std::uint64_t await_ready(std::uint64_t i) {
    std::unique_lock lock(mutex_);
    for (;;) {
      std::uint64_t ready = 0;
      while (ready < ring_.size() && slot(i + ready).ready) ++ready;
      if (ready > 0) return ready;
      if (has_room()) {
        const std::uint64_t first = claim();
        lock.unlock();
        produce_batch(0, first);
        lock.lock();
        mark_ready(first);
        continue;
      }
      consumer_waits_ = true;
      arrived_.wait(lock, [&] { return slot(i).ready; });
      consumer_waits_ = false;
    }
  }

  /// A helper thread's loop: claims batches while the ring has room, until stopped.
  void help(unsigned worker) {
    std::unique_lock lock(mutex_);
    for (;;) {
      if (!stop_ && !has_room()) {
        ++idle_helpers_;
        room_.wait(lock, [&] { return stop_ || has_room(); });
        --idle_helpers_;
      }
      if (stop_) return;
      const std::uint64_t first = claim();
      lock.unlock();
      produce_batch(worker, first);
      lock.lock();
      mark_ready(first);
      // Woken only when it waits for this batch: the consumer is usually busy making runs.
      if (consumer_waits_ && slot(consumed_).ready) arrived_.notify_one();
    }
  }

  void stop(std::vector<std::thread>& helpers) {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    room_.notify_all();
    for (std::thread& t : helpers) t.join();
  }

  unsigned threads_;
  std::function<void(unsigned, std::uint64_t, Outcome&)> produce_;
  std::vector<Slot> ring_;
  std::mutex mutex_;
  std::condition_variable arrived_, room_;
  std::uint64_t next_ = 0, consumed_ = 0;
  unsigned idle_helpers_ = 0;  // helpers waiting for room
  bool stop_ = false, consumer_waits_ = false;
};

}  // namespace smcbip::smc
