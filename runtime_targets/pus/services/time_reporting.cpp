// ST09 time reports and the ST17 connection test.
#include "time_reporting.h"

#include <limits>

namespace smcbip::pus::services {

TimeReporting::TimeReporting(std::uint32_t base_period_ms, TmOutput& out, Millis start)
    : base_period_ms_(base_period_ms), out_(out), due_(start + base_period_ms) {}

Millis TimeReporting::period() const {
  if (rate_ > 40) return std::numeric_limits<Millis>::max() / 2;
  return Millis{base_period_ms_} << rate_;
}

void TimeReporting::set_rate(const TimeReportRate& rate, Millis now) {
  rate_ = rate.rate_exponent;
  due_ = now + period();
}

std::size_t TimeReporting::tick(Millis now) {
  std::size_t reports = 0;
  while (due_ <= now) {
    out_.emit(9, 2, TimeReport{rate_, to_cuc(due_, out_.config())}, 0, due_);
    due_ += period();
    ++reports;
  }
  return reports;
}

void connection_test(const Telecommand& tc, TmOutput& out, Millis now) {
  out.emit(17, 2, NoData{}, tc.header.source_id, now);
}

}  // namespace smcbip::pus::services
