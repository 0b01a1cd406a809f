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
  /// uses its own state. Workers run at most about `ahead` runs past the one consumed last.
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
    stop_ = false;
    for (Slot& slot : ring_) slot.ready = false;
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads_; ++w) workers.emplace_back([this, w] { work(w); });
    try {
      const std::uint64_t end = consume_in_order(first, consume);
      stop(workers);
      return end;
    } catch (...) {
      stop(workers);
      throw;
    }
  }

 private:
  // Runs are claimed and handed over in batches: one lock per batch, not per run (short runs
  // would otherwise spend their time waiting for the lock).
  static constexpr std::uint64_t kBatch = 16;

  struct Slot {
    Outcome outcome{};
    std::exception_ptr error;
    bool ready = false;
  };

  Slot& slot(std::uint64_t index) { return ring_[index % ring_.size()]; }

  std::uint64_t consume_in_order(std::uint64_t i,
                                 const std::function<bool(const Outcome&)>& consume) {
    for (;;) {
      std::uint64_t ready = 0;
      {
        std::unique_lock lock(mutex_);
        arrived_.wait(lock, [&] { return slot(i).ready; });
        while (ready < ring_.size() && slot(i + ready).ready) ++ready;
      }
      // The slots stay the consumer's until consumed_ passes them: read in place.
      for (std::uint64_t k = 0; k < ready; ++k) {
        Slot& s = slot(i + k);
        if (s.error) std::rethrow_exception(s.error);
        if (!consume(s.outcome)) return i + k + 1;
      }
      {
        std::lock_guard lock(mutex_);
        for (std::uint64_t k = 0; k < ready; ++k) slot(i + k).ready = false;
        consumed_ = i += ready;
      }
      room_.notify_all();
    }
  }

  void work(unsigned worker) {
    for (;;) {
      std::uint64_t first;
      {
        std::unique_lock lock(mutex_);
        room_.wait(lock, [&] { return stop_ || next_ + kBatch <= consumed_ + ring_.size(); });
        if (stop_) return;
        first = next_;
        next_ += kBatch;
      }
      // The claimed slots are this worker's alone until it marks them ready.
      for (std::uint64_t k = 0; k < kBatch; ++k) {
        Slot& s = slot(first + k);
        s.error = nullptr;
        try {
          produce_(worker, first + k, s.outcome);
        } catch (...) {
          s.error = std::current_exception();
        }
      }
      bool awaited;
      {
        std::lock_guard lock(mutex_);
        for (std::uint64_t k = 0; k < kBatch; ++k) slot(first + k).ready = true;
        // The consumer waits for run consumed_ alone: waking it for another batch would cost a
        // context switch for nothing (short runs would spend a tenth of their time on it).
        awaited = first <= consumed_ && consumed_ < first + kBatch;
      }
      if (awaited) arrived_.notify_one();
    }
  }

  void stop(std::vector<std::thread>& workers) {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    room_.notify_all();
    for (std::thread& t : workers) t.join();
  }

  unsigned threads_;
  std::function<void(unsigned, std::uint64_t, Outcome&)> produce_;
  std::vector<Slot> ring_;
  std::mutex mutex_;
  std::condition_variable arrived_, room_;
  std::uint64_t next_ = 0, consumed_ = 0;
  bool stop_ = false;
};

}  // namespace smcbip::smc
