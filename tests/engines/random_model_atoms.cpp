// Random atom types: 1-safe nets of a main and an auxiliary token, data, clocks, priorities.
#include <algorithm>
#include <cstddef>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "random_model_generator.h"

namespace smcbip::tests::random_model_detail {

std::string Generator::data_guard(const std::vector<std::string>& ints,
                                  const std::vector<std::string>& bools) {
  auto atom = [&]() -> std::string {
    if (!bools.empty() && chance(30)) return (chance(50) ? "!" : "") + one_of(bools);
    const std::string& x = one_of(ints);
    switch (uniform(0, 3)) {
      case 0:
        return x + " < " + number(1, 5);
      case 1:
        return x + " >= " + number(1, 4);
      case 2:
        return x + " == " + number(0, 4);
      default:
        return "(" + x + " + " + one_of(ints) + ") % 2 == 0";
    }
  };
  std::string guard = atom();
  if (chance(40)) guard += (chance(60) ? " && " : " || ") + atom();
  return guard;
}

std::string Generator::data_action(const std::vector<std::string>& ints,
                                   const std::vector<std::string>& bools) {
  auto statement = [&]() -> std::string {
    const std::string& x = one_of(ints);
    switch (uniform(0, bools.empty() ? 1 : 4)) {
      case 0:
        return x + " = (" + x + " + 1) % 5;";
      case 1:
        return x + " = (" + x + " + " + one_of(ints) + " + " + number(1, 3) + ") % 7;";
      case 2:
        return one_of(bools) + " = !" + one_of(bools) + ";";
      case 3:
        return one_of(bools) + " = " + x + " < " + number(1, 4) + ";";
      default:
        return "if (" + one_of(bools) + ") then " + x + " = (" + x + " + 2) % 5; else " +
               one_of(ints) + " = 0; fi";
    }
  };
  std::string action = statement();
  if (chance(30)) action += " " + statement();
  return action;
}

std::string Generator::clock_guard(const AtomType& type) {
  const std::string& clock = one_of(type.clocks);
  const int low = uniform(0, 3);
  switch (uniform(0, 2)) {
    case 0:
      return clock + " >= " + std::to_string(low) + " && " + clock +
             " <= " + std::to_string(low + uniform(1, 4));
    case 1:
      return clock + " >= " + std::to_string(low + 1);
    default:
      return clock + " <= " + std::to_string(low + 2);
  }
}

void Generator::transition(std::ostream& out, const AtomType& type, const std::string& label,
                           const std::vector<std::string>& from, const std::vector<std::string>& to,
                           const std::string& guard) {
  const bool internal = label.empty();
  const bool timed = !internal && !type.clocks.empty();
  std::vector<std::string> conditions;
  if (timed && chance(50)) conditions.push_back(clock_guard(type));
  if (!guard.empty()) conditions.push_back(conditions.empty() ? guard : "(" + guard + ")");
  out << "    " << (internal ? "internal" : "on " + label) << " from " << join(from, ", ") << " to "
      << join(to, ", ");
  if (!conditions.empty()) out << " provided (" << join(conditions, " && ") << ")";
  if (timed && chance(60)) {
    out << " " << one_of(std::vector<std::string>{"eager", "delayable", "lazy"});
  }
  std::vector<std::string> actions;
  if (options_.data && chance(50)) actions.push_back(data_action(type.ints, type.bools));
  if (!type.clocks.empty() && chance(40)) actions.push_back(one_of(type.clocks) + " = 0;");
  if (!actions.empty()) out << " do { " << join(actions, " ") << " }";
  out << "\n";
}

void Generator::make_atom_type(int index) {
  AtomType type;
  type.name = "A" + std::to_string(index);
  std::ostringstream out;
  out << "  atom type " << type.name << (options_.data ? "(int init)" : "()") << "\n";
  if (options_.data) {
    const int ints = uniform(1, 2), bools = uniform(0, 1);
    for (int i = 0; i < ints + bools; ++i) {
      const bool is_int = i < ints;
      const std::string var = (is_int ? "x" : "b") + std::to_string(is_int ? i : i - ints);
      const bool exported = chance(50);
      (is_int ? type.ints : type.bools).push_back(var);
      if (exported) (is_int ? type.exported_ints : type.exported_bools).push_back(var);
      out << "    " << (exported ? "export data " : "data ") << (is_int ? "int " : "bool ") << var
          << "\n";
    }
  }
  if (options_.clocks && chance(80)) {
    type.clocks =
        chance(70) ? std::vector<std::string>{"t0"} : std::vector<std::string>{"t0", "t1"};
    out << "    clock " << join(type.clocks, ", ") << " unit millisecond\n";
  }

  // Places: the main token cycles through L0..Ln-1; in the places marked `aux` an auxiliary
  // token also lives in M0..Mm-1, forked when the main token enters them and joined when it
  // leaves, so the net stays 1-safe.
  const int main_places =
      uniform(std::min(2, std::max(1, options_.max_places)), std::max(1, options_.max_places));
  const int aux_places = main_places >= 2 && chance(35) ? uniform(1, 2) : 0;
  std::vector<bool> aux(static_cast<std::size_t>(main_places), false);
  if (aux_places > 0) {
    for (std::size_t i = 0; i < aux.size(); ++i) aux[i] = chance(50);
    aux[static_cast<std::size_t>(uniform(0, main_places - 1))] = true;
  }
  auto main_place = [](int i) { return "L" + std::to_string(i); };
  auto aux_place = [](int i) { return "M" + std::to_string(i); };

  const int exported_ports = uniform(1, std::max(1, options_.max_ports));
  const int internal_ports = chance(40) ? 1 : 0;
  for (int i = 0; i < exported_ports + internal_ports; ++i) {
    AtomPort port;
    port.exported = i < exported_ports;
    port.name =
        (port.exported ? "p" : "q") + std::to_string(port.exported ? i : i - exported_ports);
    if (options_.data) port.type = type.bools.empty() ? uniform(kSig, kInt) : uniform(kSig, kPair);
    port.region = aux_places > 0 && i > 0 && chance(30) ? 1 : 0;
    std::vector<std::string> args;
    if (has_int(port.type)) args.push_back(one_of(type.ints));
    if (has_bool(port.type)) args.push_back(one_of(type.bools));
    // Distributions of unbounded support: a clock already past the mean never misses it.
    if (options_.stochastic && port.exported && !type.clocks.empty() && chance(40)) {
      port.stochastic = true;
      const bool normal = chance(50);
      const std::string& clock = one_of(type.clocks);
      const std::string params = number(1, 4) + (normal ? "," + number(1, 2) : "");
      out << "    @stochastic(dist=\"" << (normal ? "normal" : "exponential") << "\", clk=" << clock
          << ", param=\"" << params << "\")\n";
    }
    out << "    " << (port.exported ? "export port " : "port ") << kPortTypeNames[port.type] << " "
        << port.name << "(" << join(args, ", ") << ")\n";
    type.ports.push_back(port);
  }

  std::vector<std::string> places;
  for (int i = 0; i < main_places; ++i) places.push_back(main_place(i));
  for (int i = 0; i < aux_places; ++i) places.push_back(aux_place(i));
  out << "    place " << join(places, ", ") << "\n";

  std::vector<std::string> inits;
  if (options_.data) {
    inits.push_back(type.ints[0] + " = init;");
    for (std::size_t i = 1; i < type.ints.size(); ++i) inits.push_back(type.ints[i] + " = 1;");
    for (const std::string& b : type.bools) inits.push_back(b + " = true;");
  }
  for (const std::string& clock : type.clocks) inits.push_back(clock + " = 0;");
  out << "    initial to " << main_place(0) << (aux[0] ? ", " + aux_place(0) : "");
  if (!inits.empty()) out << " do { " << join(inits, " ") << " }";
  out << "\n";

  // Main-token transitions: a cycle through every place, then a few extra edges. Label -1 is
  // the unlabelled internal step, allowed only towards a higher place so internal steps end.
  std::vector<int> main_labels;
  std::vector<int> aux_labels;
  for (std::size_t i = 0; i < type.ports.size(); ++i) {
    (type.ports[i].region == 0 ? main_labels : aux_labels).push_back(static_cast<int>(i));
  }
  std::vector<std::set<int>> used(static_cast<std::size_t>(main_places));
  auto free_labels = [&](int from, int to) {
    std::vector<int> labels;
    for (int label : main_labels) {
      if (!used[static_cast<std::size_t>(from)].count(label)) labels.push_back(label);
    }
    if (to > from && !used[static_cast<std::size_t>(from)].count(-1)) labels.push_back(-1);
    return labels;
  };
  auto main_move = [&](int from, int to, int label, const std::string& guard) {
    std::vector<std::string> sources{main_place(from)}, targets{main_place(to)};
    const bool aux_from = aux[static_cast<std::size_t>(from)];
    const bool aux_to = aux[static_cast<std::size_t>(to)];
    if (aux_from && aux_to && chance(30)) {
      sources.push_back(aux_place(uniform(0, aux_places - 1)));
      targets.push_back(aux_place(uniform(0, aux_places - 1)));
    } else if (!aux_from && aux_to) {
      targets.push_back(aux_place(uniform(0, aux_places - 1)));  // fork
    } else if (aux_from && !aux_to) {
      sources.push_back(aux_place(uniform(0, aux_places - 1)));  // join
    }
    transition(out, type, label < 0 ? "" : type.ports[static_cast<std::size_t>(label)].name,
               sources, targets, guard);
  };
  auto add_main = [&](int from, int to) {
    const std::vector<int> labels = free_labels(from, to);
    if (labels.empty()) return;
    const int label = one_of(labels);
    used[static_cast<std::size_t>(from)].insert(label);
    if (!options_.data || !chance(25)) {
      main_move(from, to, label,
                options_.data && chance(35) ? data_guard(type.ints, type.bools) : "");
      return;
    }
    // Two transitions of one label from one place, told apart by complementary guards.
    const std::string guard = data_guard(type.ints, type.bools);
    int other = uniform(0, main_places - 1);
    if (label < 0) other = uniform(from + 1, main_places - 1);
    main_move(from, to, label, guard);
    main_move(from, other, label, "!(" + guard + ")");
  };
  for (int i = 0; i < main_places; ++i) add_main(i, (i + 1) % main_places);
  const int extras = uniform(0, main_places);
  for (int k = 0; k < extras; ++k) {
    add_main(uniform(0, main_places - 1), uniform(0, main_places - 1));
  }
  // Auxiliary-token transitions, with the auxiliary ports only.
  for (int i = 0; i < aux_places && !aux_labels.empty(); ++i) {
    std::vector<int> labels = aux_labels;
    std::shuffle(labels.begin(), labels.end(), rng_);
    const int count = uniform(1, static_cast<int>(labels.size()));
    for (int k = 0; k < count; ++k) {
      const int to = k == 0 ? (i + 1) % aux_places : uniform(0, aux_places - 1);
      transition(out, type, type.ports[static_cast<std::size_t>(labels[k])].name, {aux_place(i)},
                 {aux_place(to)},
                 options_.data && chance(30) ? data_guard(type.ints, type.bools) : "");
    }
  }

  // Atom priorities only rank a port below a later one: no cycle.
  if (options_.priorities && type.ports.size() >= 2) {
    const int rules = uniform(0, 2);
    std::set<std::pair<int, int>> made;
    for (int r = 0; r < rules; ++r) {
      const int low = uniform(0, static_cast<int>(type.ports.size()) - 2);
      const int high = uniform(low + 1, static_cast<int>(type.ports.size()) - 1);
      if (!made.insert({low, high}).second) continue;
      out << "    priority ap" << r << " " << type.ports[static_cast<std::size_t>(low)].name
          << " < " << type.ports[static_cast<std::size_t>(high)].name;
      if (options_.data && chance(40)) {
        out << " provided (" << data_guard(type.ints, type.bools) << ")";
      }
      out << "\n";
    }
  }
  out << "  end\n\n";
  atom_types_text_ << out.str();
  atom_types_.push_back(std::move(type));
}

}  // namespace smcbip::tests::random_model_detail
