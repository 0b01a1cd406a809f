// The user-written externs of the BIP conformance models, behaving as EXPECTED.md section 10
// describes the original tempcontrol-print and MyExternalPort* sources.
#include "tests/engines/conformance_externs.h"

#include <algorithm>
#include <iomanip>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <utility>

namespace smcbip::tests {
namespace {

using engines::ExternEvent;
using engines::ExternPortSource;
using engines::TimeValue;

constexpr TimeValue kMillisecond = 1'000'000;

/// The clock shared by the "MyExternalPortSum" ports of one model run: each event of any of
/// them is stamped at the previous stamp plus a uniform delay in [20 ms, 40 ms).
///
/// One run is recognised as one *batch* of factory calls: a new batch (fresh clock, same fixed
/// seed, so every run sees the same delays) starts when no source of the previous batch is
/// alive any more, or when a port that already belongs to the current batch is created again
/// (a second run while the first one's sources are still held).
class SumClock {
 public:
  /// Joins `atom.port` to this batch; false when it is already part of it.
  bool join(const std::string& atom_path, const std::string& port_name) {
    const std::lock_guard lock(mutex_);
    return ports_.emplace(atom_path, port_name).second;
  }

  /// The stamp of the next event of any port of the batch. Stamps never lie before `now`: when
  /// the engine keeps up this is exactly the rule above; when it lags (a loaded machine, in
  /// real time) it keeps the producer from inventing an outdated event the original, whose
  /// producers ran on the wall clock, would not have produced.
  TimeValue next_stamp(TimeValue now) {
    const std::lock_guard lock(mutex_);
    last_ = std::max(last_, now) + delay_(random_);
    return last_;
  }

 private:
  std::mutex mutex_;  // the multithread engine may pull several ports at once
  std::set<std::pair<std::string, std::string>> ports_;
  std::mt19937_64 random_{kSumDelaySeed};
  std::uniform_int_distribution<TimeValue> delay_{20 * kMillisecond, 40 * kMillisecond - 1};
  TimeValue last_ = 0;
};

/// "MyExternalPortSum": 100 events; the i-th carries x = 1 + 2 + ... + i.
class SumSource final : public ExternPortSource {
 public:
  explicit SumSource(std::shared_ptr<SumClock> clock) : clock_(std::move(clock)) {}

  std::optional<ExternEvent> next(TimeValue now) override {
    if (sent_ == kSumEventsPerPort) return std::nullopt;
    ++sent_;
    return ExternEvent{clock_->next_stamp(now), {engines::make_int(sent_ * (sent_ + 1) / 2)}};
  }

 private:
  std::shared_ptr<SumClock> clock_;
  std::int64_t sent_ = 0;
};

/// "MyExternalPortSingle": one event x = 42, at the time the engine first asks.
class SingleSource final : public ExternPortSource {
 public:
  std::optional<ExternEvent> next(TimeValue now) override {
    if (sent_) return std::nullopt;
    sent_ = true;
    return ExternEvent{now, {engines::make_int(42)}};
  }

 private:
  bool sent_ = false;
};

/// The factory of "MyExternalPortSum", holding the current batch's clock weakly so that the
/// clock dies with the run's sources.
engines::ExternPortFactory sum_factory() {
  struct Batches {
    std::mutex mutex;
    std::weak_ptr<SumClock> current;
  };
  auto batches = std::make_shared<Batches>();
  return [batches](const std::string& atom_path,
                   const std::string& port_name) -> std::unique_ptr<ExternPortSource> {
    const std::lock_guard lock(batches->mutex);
    std::shared_ptr<SumClock> clock = batches->current.lock();
    if (!clock || !clock->join(atom_path, port_name)) {
      clock = std::make_shared<SumClock>();
      clock->join(atom_path, port_name);
      batches->current = clock;
    }
    return std::make_unique<SumSource>(std::move(clock));
  };
}

}  // namespace

std::string tempcontrol_row(std::int64_t step, std::int64_t temperature, const std::string& rod1,
                            const std::string& rod2, const std::string& command1,
                            const std::string& command2) {
  std::ostringstream row;
  row << std::right << std::setw(6) << step << std::setw(12) << temperature << std::setw(8) << rod1
      << std::setw(8) << rod2 << std::setw(12) << command1 << std::setw(12) << command2;
  return std::move(row).str();
}

std::string tempcontrol_position(std::int64_t position) {
  switch (position) {
    case 0:
      return "down";
    case 1:
      return "rest";
    case 2:
      return "ready";
    default:
      return "ERROR!";
  }
}

std::string tempcontrol_command(std::int64_t command) {
  switch (command) {
    case 0:
      return "up";
    case 1:
      return "down";
    case 2:
      return "Shutdown!";
    default:
      return "ERROR!";
  }
}

void register_conformance_externs(engines::Externs& externs) {
  using engines::CallContext;
  externs.add("print", [](CallContext& context, std::string text) { context.out << text; });
  externs.add("print_position",
              [](std::int64_t position) { return tempcontrol_position(position); });
  externs.add("print_command", [](std::int64_t command) { return tempcontrol_command(command); });
  externs.add(
      "print", [](CallContext& context, std::int64_t step, std::int64_t temperature,
                  std::string rod1, std::string rod2, std::string command1, std::string command2) {
        context.out << tempcontrol_row(step, temperature, rod1, rod2, command1, command2) << '\n';
      });

  externs.add_port_class("MyExternalPortSum", sum_factory());
  externs.add_port_class(
      "MyExternalPortSingle",
      [](const std::string&, const std::string&) -> std::unique_ptr<ExternPortSource> {
        return std::make_unique<SingleSource>();
      });
}

}  // namespace smcbip::tests
