// The on-board application: routing TCs to the services and running their periodic work.
#include "application.h"

#include <algorithm>

namespace smcbip::pus::services {

Application::Application(const mission::Mission& mission, const Config& config, Millis start)
    : mission_(mission),
      config_(config),
      tm_(config, mission.apid),
      verification_(tm_),
      reception_(config, mission.apid, verification_),
      parameters_(mission),
      events_(mission, tm_),
      functions_(mission, parameters_),
      housekeeping_(mission, parameters_, tm_, start),
      time_(mission.time_report_period_ms, tm_, start),
      monitoring_(mission, parameters_, start),
      event_action_(mission),
      files_(mission) {
  // Room for every definition's transition in one step, so tick() does not allocate.
  transitions_.reserve(mission.monitoring.size());
}

void Application::receive(std::span<const std::uint8_t> bytes, Millis now) {
  if (const auto tc = reception_.receive(bytes, now)) execute(*tc, now);
}

Outcome Application::dispatch(const Telecommand& tc, Millis now) {
  const std::uint8_t subtype = tc.header.subtype;
  switch (*TcReception::route(tc)) {
    case Route::Housekeeping:
      return housekeeping_.set_enabled(std::get<IdList>(tc.data), subtype == 5, now);
    case Route::Events:
      return events_.set_enabled(std::get<IdList>(tc.data), subtype == 5);
    case Route::Functions:
      return functions_.perform(std::get<FunctionCall>(tc.data));
    case Route::Time:
      time_.set_rate(std::get<TimeReportRate>(tc.data), now);
      return std::nullopt;
    case Route::Scheduling:
      return schedule_.insert(std::get<Activities>(tc.data), config_, now);
    case Route::Monitoring:
      return monitoring_.set_enabled(std::get<IdList>(tc.data), subtype == 1, now);
    case Route::Test:
      connection_test(tc, tm_, now);
      return std::nullopt;
    case Route::EventAction:
      return subtype == 1 ? event_action_.add(std::get<Activities>(tc.data))
                          : event_action_.enable(std::get<IdList>(tc.data));
    case Route::Parameters:
      return subtype == 1
                 ? parameters_.report(std::get<IdList>(tc.data), tc.header.source_id, tm_, now)
                 : parameters_.set_all(std::get<ParameterValues>(tc.data));
    case Route::Files:
      return files_.execute(tc, tm_, now);
  }
  return Failure{FailureCode::NotRouted, tc.header.service};
}

Outcome Application::check(const Telecommand& tc, Millis now) const {
  // The decoder guarantees the data's alternative matches the message type.
  switch (*TcReception::route(tc)) {
    case Route::Housekeeping:
      return housekeeping_.check(std::get<IdList>(tc.data));
    case Route::Events:
      return events_.check(std::get<IdList>(tc.data));
    case Route::Functions:
      return functions_.check(std::get<FunctionCall>(tc.data));
    case Route::Time:
    case Route::Test:
      return std::nullopt;
    case Route::Scheduling:
      return schedule_.check(std::get<Activities>(tc.data), config_, now);
    case Route::Monitoring:
      return monitoring_.check(std::get<IdList>(tc.data));
    case Route::EventAction:
      return tc.header.subtype == 1 ? event_action_.check(std::get<Activities>(tc.data))
                                    : event_action_.check(std::get<IdList>(tc.data));
    case Route::Parameters:
      return tc.header.subtype == 1 ? parameters_.check(std::get<IdList>(tc.data))
                                    : parameters_.check(std::get<ParameterValues>(tc.data));
    case Route::Files:
      return files_.check(tc);
  }
  return Failure{FailureCode::NotRouted, tc.header.service};
}

void Application::execute(const Telecommand& tc, Millis now) {
  if (const Outcome refused = check(tc, now)) {
    verification_.start_failed(tc, *refused, now);
    return;
  }
  verification_.started(tc, now);
  if (const Outcome failed = dispatch(tc, now)) {
    verification_.completion_failed(tc, *failed, now);
    return;
  }
  if (const auto* activities = std::get_if<Activities>(&tc.data)) {
    for (std::size_t step = 1; step <= activities->items.size(); ++step) {
      verification_.progressed(tc, step, now);
    }
  }
  verification_.completed(tc, now);
}

std::optional<Millis> Application::next_due() const {
  std::optional<Millis> due = time_.next_due();
  for (const auto other :
       {housekeeping_.next_due(), monitoring_.next_due(), schedule_.next_due()}) {
    if (other && (!due || *other < *due)) due = other;
  }
  return due;
}

void Application::raise(const Transition& transition, Millis at) {
  const auto aux = event_aux(transition);
  if (!events_.raise(transition.event, aux, at)) return;
  if (const auto action = event_action_.on_event(transition.event)) receive(action->span(), at);
}

void Application::step(Millis at) {
  housekeeping_.tick(at);
  time_.tick(at);
  transitions_.clear();
  monitoring_.tick(at, transitions_);
  for (const Transition& t : transitions_) {
    if (violation(t.to)) raise(t, at);
  }
  while (const auto request = schedule_.release(at)) receive(request->span(), at);
}

void Application::tick(Millis now) {
  for (auto due = next_due(); due && *due <= now; due = next_due()) step(*due);
}

}  // namespace smcbip::pus::services
