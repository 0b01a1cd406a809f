// Runs produced on several threads and consumed in run-index order, as if one thread had made
// them: a sequential test then sees the same outcomes, and stops at the same run, whatever
// thread finished first (Younes 2005, unbiased parallel sampling).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace smcbip::smc {

template <class Outcome>
class OrderedSampler {
 public:
  /// `produce(worker, index)` makes run `index` on thread `worker` (0..threads-1); each worker
  /// uses its own state. Workers run at most `ahead` runs past the one consumed last.
  OrderedSampler(unsigned threads, std::function<Outcome(unsigned, std::uint64_t)> produce,
                 std::uint64_t ahead = 256)
      : threads_(threads == 0 ? 1 : threads), produce_(std::move(produce)), ahead_(ahead) {}

  /// Calls `consume` with the outcomes of runs first, first + 1, ... until it returns false;
  /// returns the index after the last consumed.
  std::uint64_t run(std::uint64_t first, const std::function<bool(const Outcome&)>& consume) {
    if (threads_ == 1) {
      std::uint64_t i = first;
      while (consume(produce_(0, i++))) {
      }
      return i;
    }
    next_ = first;
    consumed_ = first;
    stop_ = false;
    ready_.clear();
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < threads_; ++w) workers.emplace_back([this, w] { work(w); });
    std::uint64_t i = first;
    std::vector<Slot> taken;
    for (;;) {
      {
        // Every outcome ready from i on, in one visit.
        std::unique_lock lock(mutex_);
        arrived_.wait(lock, [&] { return ready_.contains(i); });
        taken.clear();
        for (auto it = ready_.find(i); it != ready_.end() && it->first == i + taken.size();) {
          taken.push_back(std::move(it->second));
          it = ready_.erase(it);
        }
        consumed_ = i + taken.size();
      }
      room_.notify_all();
      for (Slot& slot : taken) {
        ++i;
        if (slot.error || !consume(slot.outcome)) {
          stop(workers);
          if (slot.error) std::rethrow_exception(slot.error);
          return i;
        }
      }
    }
  }

 private:
  // Runs are claimed and handed over in batches: one lock per batch, not per run (short runs
  // would otherwise spend their time waiting for the lock).
  static constexpr std::uint64_t kBatch = 16;

  void work(unsigned worker) {
    std::vector<Slot> made;
    for (;;) {
      std::uint64_t first;
      {
        std::unique_lock lock(mutex_);
        room_.wait(lock, [&] { return stop_ || next_ < consumed_ + ahead_; });
        if (stop_) return;
        first = next_;
        next_ += kBatch;
      }
      made.assign(kBatch, Slot{});
      for (std::uint64_t k = 0; k < kBatch; ++k) {
        try {
          made[k].outcome = produce_(worker, first + k);
        } catch (...) {
          made[k].error = std::current_exception();  // rethrown when its turn comes
          made.resize(k + 1);
          break;
        }
      }
      {
        std::lock_guard lock(mutex_);
        for (std::uint64_t k = 0; k < made.size(); ++k)
          ready_.emplace(first + k, std::move(made[k]));
      }
      arrived_.notify_one();
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

  struct Slot {
    Outcome outcome{};
    std::exception_ptr error;
  };

  unsigned threads_;
  std::function<Outcome(unsigned, std::uint64_t)> produce_;
  std::uint64_t ahead_;
  std::mutex mutex_;
  std::condition_variable arrived_, room_;
  std::map<std::uint64_t, Slot> ready_;
  std::uint64_t next_ = 0, consumed_ = 0;
  bool stop_ = false;
};

}  // namespace smcbip::smc
