#include "engines/stochastic/date_planner.h"

#include <cmath>
#include <limits>

namespace smcbip::engines {

namespace {

bool same(const Constraint& a, const Constraint& b) {
  const Interval& x = a.interval;
  const Interval& y = b.interval;
  return a.urgency == b.urgency && x.left == y.left && x.right == y.right &&
         x.left_open == y.left_open && x.right_open == y.right_open;
}

/// `delay` nanoseconds after `from`, saturating at +infinity.
TimeValue after(TimeValue from, double delay) {
  if (!(delay < static_cast<double>(kPlusInfinity - from))) return kPlusInfinity;
  return from + static_cast<TimeValue>(delay);
}

}  // namespace

std::string load_custom_distributions(const bipc::ir::System& system, CustomDistributions& out) {
  for (const bipc::ir::AtomType& type : system.atom_types) {
    for (const bipc::ir::Port& port : type.ports) {
      if (!port.stochastic || port.stochastic->distribution != bipc::ir::Distribution::Custom) {
        continue;
      }
      const std::string& file = port.stochastic->custom_file;
      if (out.count(file)) continue;
      auto loaded = EmpiricalCdf::load(file);
      if (auto* message = std::get_if<std::string>(&loaded)) return *message;
      out.emplace(file, std::get<EmpiricalCdf>(std::move(loaded)));
    }
  }
  return {};
}

bool has_stochastic_ports(const bipc::ir::System& system) {
  for (const bipc::ir::AtomType& type : system.atom_types) {
    for (const bipc::ir::Port& port : type.ports) {
      if (port.stochastic) return true;
    }
  }
  return false;
}

DatePlanner::DatePlanner(const bipc::ir::System& system, const CustomDistributions& custom,
                         RandomStream& random, TimeValue unbounded_mean)
    : system_(system), random_(random), unbounded_mean_(unbounded_mean), custom_(custom) {}

std::size_t DatePlanner::KeyHash::operator()(const std::vector<std::uint32_t>& key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::uint32_t x : key) h = (h ^ x) * 0xff51afd7ed558ccdull;
  return static_cast<std::size_t>(h ^ (h >> 32));
}

std::vector<std::uint32_t> DatePlanner::key_of(const Runtime& runtime, const Item& item) const {
  std::vector<std::uint32_t> key;
  key.push_back(static_cast<std::uint32_t>(item.kind));
  if (item.kind == Item::Kind::Interaction) {
    const InteractionValue& value = runtime.values()[item.value];
    key.push_back(value.connector);
    key.push_back(value.defined);
  }
  for (const auto& [atom, port] : runtime.atom_ports(item)) {
    key.push_back(atom);
    key.push_back(port);
  }
  return key;
}

bool DatePlanner::plan(Runtime& runtime, std::vector<TimeValue>& dates, std::string& error) {
  dates.clear();
  next_plans_.clear();
  for (const Item& item : runtime.items()) {
    std::vector<std::uint32_t> key = key_of(runtime, item);
    auto kept = plans_.find(key);
    TimeValue date = 0;
    if (kept != plans_.end() && same(kept->second.offered, item.offered)) {
      date = kept->second.date;
    } else if (!draw(runtime, item, date, error)) {
      return false;
    }
    dates.push_back(date);
    next_plans_.insert_or_assign(std::move(key), Planned{item.offered, date});
  }
  std::swap(plans_, next_plans_);
  return true;
}

bool DatePlanner::draw(Runtime& runtime, const Item& item, TimeValue& date, std::string& error) {
  // The item's own window from now: the dates other items' deadlines cut off stay possible, as
  // the race decides whether the item gets there.
  const Interval window = item.offered.interval.intersect(Interval::from(runtime.state().now));
  for (const auto& [atom, port] : runtime.atom_ports(item)) {
    const auto& type = system_.atom_types[system_.atoms[atom].type];
    if (type.ports[port].stochastic) {
      return draw_stochastic(runtime, atom, port, window, date, error);
    }
  }
  date = draw_timed(item.offered.urgency, window);
  return true;
}

bool DatePlanner::is_stochastic(const Runtime& runtime, const Item& item) const {
  for (const auto& [atom, port] : runtime.atom_ports(item)) {
    if (system_.atom_types[system_.atoms[atom].type].ports[port].stochastic) return true;
  }
  return false;
}

void DatePlanner::replan_within_windows(const Runtime& runtime, std::vector<TimeValue>& dates) {
  const std::vector<Item>& items = runtime.items();
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (is_stochastic(runtime, items[i])) continue;
    dates[i] = draw_timed(items[i].constraint.urgency, items[i].constraint.interval);
    std::vector<std::uint32_t> key = key_of(runtime, items[i]);
    plans_.insert_or_assign(std::move(key), Planned{items[i].offered, dates[i]});
  }
}

TimeValue DatePlanner::draw_timed(bipc::Urgency urgency, const Interval& window) {
  const TimeValue first = window.first();
  if (urgency == bipc::Urgency::Eager) return first;
  if (window.bounded()) {
    const TimeValue last = window.last();
    if (last <= first) return first;
    return first + static_cast<TimeValue>(random_.below(static_cast<std::uint64_t>(last - first) + 1));
  }
  const double delay = -static_cast<double>(unbounded_mean_) * std::log(random_.uniform01_open());
  return after(first, std::floor(delay));
}

bool DatePlanner::draw_stochastic(Runtime& runtime, Index atom, Index port, const Interval& window,
                                  TimeValue& date, std::string& error) {
  const auto& type = system_.atom_types[system_.atoms[atom].type];
  const bipc::ir::Stochastic& annotation = *type.ports[port].stochastic;
  const std::vector<double> params = runtime.stochastic_params(atom, port);
  const EmpiricalCdf* custom = nullptr;
  if (annotation.distribution == bipc::ir::Distribution::Custom) {
    custom = &custom_.at(annotation.custom_file);
  }
  const std::string where = runtime.layout().atom_names[atom] + "." + type.ports[port].name;
  auto made = DateDistribution::make(annotation.distribution, params, custom);
  if (auto* message = std::get_if<std::string>(&made)) {
    error = "@stochastic distribution of " + where + ": " + *message;
    return false;
  }
  const DateDistribution& distribution = std::get<DateDistribution>(made);
  // The date is drawn on the clock's scale, conditioned on lying in the port's window: a
  // clock that has already advanced truncates the distribution at its value.
  const double lower = runtime.clock_value(atom, annotation.clock, window.first());
  double sample = 0.0;
  if (distribution.cdf(lower) > 0.0) {
    const std::optional<double> above = distribution.sample_above(lower, random_);
    if (!above) {
      error = "missed support: " + where + " draws from " + distribution.describe() +
              " but its clock " + type.clocks[annotation.clock].name + " is already at " +
              std::to_string(lower) + ", beyond every date of the distribution";
      return false;
    }
    sample = *above;
  } else {
    sample = distribution.sample(random_);
  }
  date = std::max(window.first(), runtime.clock_reaches(atom, annotation.clock, sample));
  return true;
}

}  // namespace smcbip::engines
