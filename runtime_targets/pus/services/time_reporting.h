// ST09 time management: periodic CUC time reports at a rate set by [9,1].
#pragma once

#include <cstdint>

#include "packets/packets.h"
#include "tm_output.h"

namespace smcbip::pus::services {

/// Reports [9,2] every 2^rate base periods (ECSS-E-ST-70-41C 6.9.4.1: the exponential rate).
class TimeReporting {
 public:
  TimeReporting(std::uint32_t base_period_ms, TmOutput& out, Millis start);

  /// [9,1]: the new rate applies from now (the next report one new period later).
  void set_rate(const TimeReportRate& rate, Millis now);
  /// Emits the reports due at or before `now`; returns how many.
  std::size_t tick(Millis now);
  Millis next_due() const { return due_; }
  /// The period at the current rate; saturates (no report ever) past 2^40 base periods.
  Millis period() const;

 private:
  std::uint32_t base_period_ms_;
  TmOutput& out_;
  std::uint8_t rate_ = 0;
  Millis due_;
};

/// ST17: [17,1] is answered by [17,2], to the TC's source.
void connection_test(const Telecommand& tc, TmOutput& out, Millis now);

}  // namespace smcbip::pus::services
