#include "engines/stochastic/date_planner.h"

#include <cmath>

namespace smcbip::engines {

TimeValue uniform_date(const Interval& window, RandomStream& random) {
  const TimeValue first = window.first();
  const TimeValue last = window.last();
  if (last <= first) return first;
  return first + static_cast<TimeValue>(random.below(static_cast<std::uint64_t>(last - first) + 1));
}

namespace {

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
    : system_(system), random_(random), unbounded_mean_(unbounded_mean), custom_(custom) {
  for (const bipc::ir::AtomInstance& atom : system.atoms) {
    first_port_.push_back(stochastic_ports_.size());
    for (const bipc::ir::Port& port : system.atom_types[atom.type].ports) {
      stochastic_ports_.push_back(port.stochastic ? 1 : 0);
      port_clocks_.push_back(port.stochastic ? port.stochastic->clock : 0);
      fixed_distributions_.push_back(port.stochastic ? fixed_distribution(*port.stochastic)
                                                     : std::nullopt);
    }
  }
}

std::optional<DatePlanner::Fixed> DatePlanner::fixed_distribution(
    const bipc::ir::Stochastic& annotation) const {
  std::vector<double> params;
  for (const bipc::ir::Code& code : annotation.params) {
    const std::optional<double> number = number_param(code);
    if (!number) return std::nullopt;
    params.push_back(*number);
  }
  // Invalid parameters are left to each draw, which reports them.
  auto made = make_distribution(annotation, params);
  if (auto* distribution = std::get_if<DateDistribution>(&made)) return Fixed(*distribution);
  return std::nullopt;
}

std::variant<DateDistribution, std::string> DatePlanner::make_distribution(
    const bipc::ir::Stochastic& annotation, std::span<const double> params) const {
  const EmpiricalCdf* custom = nullptr;
  if (annotation.distribution == bipc::ir::Distribution::Custom) {
    const auto found = custom_.find(annotation.custom_file);
    if (found != custom_.end()) custom = &found->second;
  }
  return DateDistribution::make(annotation.distribution, params, custom);
}

DateDistribution::Masses DatePlanner::Fixed::masses(double x) {
  if (x != lower) {
    lower = x;
    at_lower = distribution.masses(x);
  }
  return at_lower;
}

std::size_t DatePlanner::KeyHash::operator()(std::span<const std::pair<Index, Index>> key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const auto& [first, second] : key) {
    h = (h ^ first) * 0xff51afd7ed558ccdull;
    h = (h ^ second) * 0xff51afd7ed558ccdull;
  }
  return static_cast<std::size_t>(h ^ (h >> 32));
}

void DatePlanner::key_of(const Runtime& runtime, const Item& item) {
  const InteractionValue& value = runtime.values()[item.value];
  key_.clear();
  key_.emplace_back(value.connector, value.defined);
  runtime.append_atom_ports(item, key_);
}

void DatePlanner::index_connectors(const Runtime& runtime) {
  indexed_ = true;
  port_plans_.resize(stochastic_ports_.size());
  connector_plans_.resize(system_.connectors.size());
  connector_stochastic_.resize(system_.connectors.size());
  for (Index k = 0; k < system_.connectors.size(); ++k) {
    // Each port binding exactly one atom port: the interaction decides the atom ports.
    bool atom_per_port = true;
    for (const auto& refs : system_.connectors[k].bound) {
      atom_per_port =
          atom_per_port && refs.size() == 1 && refs.front().kind == bipc::ir::PortRef::Kind::Atom;
    }
    const std::vector<DefinedInteraction>& defined = runtime.layout().defined[k];
    if (!atom_per_port || defined.size() > kDirectPlans) continue;
    for (const DefinedInteraction& interaction : defined) {
      connector_plans_[k].push_back({});
      connector_stochastic_[k].push_back(stochastic_port_of(k, interaction.ports));
    }
  }
}

std::optional<std::pair<Index, Index>> DatePlanner::stochastic_port_of(Index k,
                                                                       PortSet ports) const {
  const auto& bound = system_.connectors[k].bound;
  for (std::size_t i = 0; i < bound.size(); ++i) {
    const bipc::ir::PortRef& ref = bound[i].front();
    if ((ports & (PortSet{1} << i)) && stochastic_ports_[first_port_[ref.instance] + ref.port]) {
      return std::pair{ref.instance, ref.port};
    }
  }
  return std::nullopt;
}

DatePlanner::Plan& DatePlanner::plan_of(const Runtime& runtime, const Item& item) {
  if (item.kind != Item::Kind::Interaction) return port_plans_[first_port_[item.atom] + item.port];
  const InteractionValue& value = runtime.values()[item.value];
  std::vector<Plan>& direct = connector_plans_[value.connector];
  if (value.defined < direct.size()) return direct[value.defined];
  key_of(runtime, item);
  auto found = plans_.find(std::span<const std::pair<Index, Index>>(key_));
  if (found == plans_.end()) found = plans_.emplace(key_, Plan{}).first;
  return found->second;
}

bool DatePlanner::plan(Runtime& runtime, std::vector<TimeValue>& dates, std::string& error) {
  if (!indexed_) index_connectors(runtime);
  dates.clear();
  ++generation_;
  for (const Item& item : runtime.items()) {
    Plan& planned = plan_of(runtime, item);
    if (!renew(
            runtime, planned, generation_, item.offered,
            [&] { return stochastic_port(runtime, item); }, error)) {
      return false;
    }
    dates.push_back(planned.date);
  }
  // Items not enabled now lose their dates: they draw afresh when enabled again.
  if (plans_.size() > 2 * runtime.items().size() + 16) {
    std::erase_if(plans_, [&](const auto& entry) { return entry.second.seen != generation_; });
  }
  return true;
}

std::optional<std::pair<Index, Index>> DatePlanner::stochastic_port(const Runtime& runtime,
                                                                    const Item& item) {
  if (item.kind != Item::Kind::Interaction) {
    if (stochastic_ports_[first_port_[item.atom] + item.port])
      return std::pair{item.atom, item.port};
    return std::nullopt;
  }
  const InteractionValue& value = runtime.values()[item.value];
  if (value.defined < connector_plans_[value.connector].size()) {
    return connector_stochastic_[value.connector][value.defined];
  }
  ports_.clear();
  runtime.append_atom_ports(item, ports_);
  for (const auto& [atom, port] : ports_) {
    if (stochastic_ports_[first_port_[atom] + port]) return std::pair{atom, port};
  }
  return std::nullopt;
}

void DatePlanner::replan_within_windows(const Runtime& runtime, std::vector<TimeValue>& dates) {
  const std::vector<Item>& items = runtime.items();
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (stochastic_port(runtime, items[i])) continue;
    dates[i] = draw_timed(items[i].constraint.urgency, items[i].constraint.interval);
    plan_of(runtime, items[i]).date = dates[i];
  }
}

TimeValue DatePlanner::draw_timed(bipc::Urgency urgency, const Interval& window) {
  const TimeValue first = window.first();
  if (urgency == bipc::Urgency::Eager) return first;
  if (window.bounded()) return uniform_date(window, random_);
  const double delay = -static_cast<double>(unbounded_mean_) * std::log(random_.uniform01_open());
  return after(first, std::floor(delay));
}

bool DatePlanner::draw_made(Runtime& runtime, Index atom, Index port, const Interval& window,
                            TimeValue& date, std::string& error) {
  runtime.stochastic_params(atom, port, params_);
  auto made = make_distribution(annotation_of(atom, port), params_);
  if (auto* message = std::get_if<std::string>(&made)) {
    error = "@stochastic distribution of " + port_name(runtime, atom, port) + ": " + *message;
    return false;
  }
  return draw_from(runtime, atom, port, std::get<DateDistribution>(made), nullptr, window, date,
                   error);
}

bool DatePlanner::missed_support(const Runtime& runtime, Index atom, Index port,
                                 const DateDistribution& distribution, double lower,
                                 std::string& error) const {
  const auto& type = system_.atom_types[system_.atoms[atom].type];
  error = "missed support: " + port_name(runtime, atom, port) + " draws from " +
          distribution.describe() + " but its clock " +
          type.clocks[annotation_of(atom, port).clock].name + " is already at " +
          std::to_string(lower) + ", beyond every date of the distribution";
  return false;
}

const bipc::ir::Stochastic& DatePlanner::annotation_of(Index atom, Index port) const {
  return *system_.atom_types[system_.atoms[atom].type].ports[port].stochastic;
}

std::string DatePlanner::port_name(const Runtime& runtime, Index atom, Index port) const {
  return runtime.layout().atom_names[atom] + "." +
         system_.atom_types[system_.atoms[atom].type].ports[port].name;
}

std::optional<DatePlanner::FixedDraw> DatePlanner::fixed_draw(const Runtime& runtime, Index atom,
                                                              Index port) {
  std::optional<Fixed>& fixed = fixed_distributions_[first_port_[atom] + port];
  if (!fixed) return std::nullopt;
  FixedDraw draw;
  draw.fixed = &*fixed;
  draw.clock = runtime.layout().atom_clocks[atom] + port_clocks_[first_port_[atom] + port];
  draw.unit = runtime.layout().clock_units[draw.clock];
  draw.atom = atom;
  draw.port = port;
  return draw;
}

}  // namespace smcbip::engines
