// ST20: parameter values, checked against the mission's limits.
#include "parameters.h"

namespace smcbip::pus::services {

ParameterStore::ParameterStore(const mission::Mission& mission) : mission_(mission) {
  raw_.reserve(mission.parameters.size());
  for (const mission::Parameter& p : mission.parameters) {
    raw_.push_back(mission::to_raw(p.type, p.initial));
  }
}

bool ParameterStore::get(std::uint64_t id, std::uint64_t& raw) const {
  const std::size_t i = mission_.parameter_index(id);
  if (i == raw_.size()) return false;
  raw = raw_[i];
  return true;
}

double ParameterStore::value(std::uint64_t id) const {
  const std::size_t i = mission_.parameter_index(id);
  return i == raw_.size() ? 0 : mission::from_raw(mission_.parameters[i].type, raw_[i]);
}

Outcome ParameterStore::check(std::uint64_t id, std::uint64_t raw) const {
  const std::size_t i = mission_.parameter_index(id);
  const auto datum = static_cast<std::uint32_t>(id);
  if (i == raw_.size()) return Failure{FailureCode::UnknownId, datum};
  const mission::Parameter& p = mission_.parameters[i];
  const double v = mission::from_raw(p.type, raw);
  // Raw bits that do not read back to themselves (a bool of 2, a NaN) are not values of the type.
  if (raw > 0xFFFFFFFFU || mission::to_raw(p.type, v) != raw || !(v >= p.min && v <= p.max)) {
    return Failure{FailureCode::InvalidArgument, datum};
  }
  return std::nullopt;
}

Outcome ParameterStore::set(std::uint64_t id, std::uint64_t raw) {
  if (Outcome failure = check(id, raw)) return failure;
  raw_[mission_.parameter_index(id)] = raw;
  return std::nullopt;
}

Outcome ParameterStore::check(const IdList& ids) const {
  std::uint64_t raw = 0;
  for (const std::uint64_t id : ids.ids) {
    if (!get(id, raw)) return Failure{FailureCode::UnknownId, static_cast<std::uint32_t>(id)};
  }
  return std::nullopt;
}

Outcome ParameterStore::check(const ParameterValues& values) const {
  for (const IdValue& item : values.values) {
    if (Outcome failure = check(item.id, item.value)) return failure;
  }
  return std::nullopt;
}

Outcome ParameterStore::report(const IdList& ids, std::uint16_t destination, TmOutput& out,
                               Millis now) const {
  if (Outcome failure = check(ids)) return failure;
  ParameterValues report;
  for (const std::uint64_t id : ids.ids) {
    std::uint64_t raw = 0;
    get(id, raw);
    report.values.push_back(IdValue{id, raw});
  }
  out.emit(20, 2, report, destination, now);
  return std::nullopt;
}

Outcome ParameterStore::set_all(const ParameterValues& values) {
  if (Outcome failure = check(values)) return failure;
  for (const IdValue& item : values.values) raw_[mission_.parameter_index(item.id)] = item.value;
  return std::nullopt;
}

}  // namespace smcbip::pus::services
