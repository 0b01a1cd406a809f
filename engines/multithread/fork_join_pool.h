// A small fork-join thread pool for running many short tasks (microseconds each) at once, with
// little latency per fork: idle workers spin briefly before they block.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace smcbip::engines::multithread {

class ForkJoinPool {
 public:
  /// A pool of `threads` threads in all: the caller of run() and `threads - 1` workers.
  explicit ForkJoinPool(unsigned threads);
  /// Stops and joins the workers.
  ~ForkJoinPool();
  ForkJoinPool(const ForkJoinPool&) = delete;
  ForkJoinPool& operator=(const ForkJoinPool&) = delete;

  /// The number of threads, the caller included: thread indices passed to tasks are below it.
  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Calls `task(i, thread)` for every i in [0, count), spread over the pool's threads (the
  /// caller is thread 0), and returns when all calls have returned. `task` must not throw.
  /// Calls on one thread are sequential; run() itself must not be called concurrently.
  template <class Task>
  void run(std::size_t count, Task& task) {
    run_erased(count, &call<Task>, &task);
  }

 private:
  using Erased = void (*)(void* task, std::size_t index, unsigned thread);
  template <class Task>
  static void call(void* task, std::size_t index, unsigned thread) {
    (*static_cast<Task*>(task))(index, thread);
  }

  void run_erased(std::size_t count, Erased fn, void* task);
  void work(unsigned thread);
  /// Claims and runs tasks of fork `epoch` until none is left unclaimed.
  void drain(std::uint32_t epoch, unsigned thread);

  // The current fork and how many of its tasks are unclaimed: epoch in the high half, count in
  // the low half, so that a late worker can never claim a task of a later fork believing it
  // belongs to an earlier one.
  std::atomic<std::uint64_t> work_{0};
  std::atomic<std::size_t> chunk_{1};
  std::atomic<std::size_t> completed_{0};
  std::atomic<unsigned> sleepers_{0};
  std::atomic<bool> joiner_waiting_{false};
  std::atomic<bool> stop_{false};
  // Written before a fork is published, read only by threads that claimed one of its tasks.
  Erased fn_ = nullptr;
  void* task_ = nullptr;
  std::size_t count_ = 0;
  std::uint32_t epoch_ = 0;  // the caller's count of forks
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
};

}  // namespace smcbip::engines::multithread
