// Random valid BIP2 packages: atom types, sub-compounds, connectors and priorities drawn by seed.
#include "random_model.h"

#include <algorithm>
#include <cstddef>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace smcbip::tests {

namespace {

/// The port types every package declares; an atom port binds data of the matching types.
enum PortType { kSig = 0, kInt = 1, kBool = 2, kPair = 3 };
constexpr const char* kPortTypeNames[] = {"Sig", "IntPort", "BoolPort", "PairPort"};

bool has_int(int type) { return type == kInt || type == kPair; }
bool has_bool(int type) { return type == kBool || type == kPair; }

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) text += (i == 0 ? "" : separator) + items[i];
  return text;
}

/// A port of an atom type. Region 0 ports label transitions of the main token, region 1 ports
/// those of the auxiliary token only, so that two transitions of one port are never enabled
/// together (each token sits in one place, and each (place, port) has one transition or two
/// with complementary guards).
struct AtomPort {
  std::string name;
  int type = kSig;
  bool exported = true;
  int region = 0;
};

struct AtomType {
  std::string name;
  std::vector<std::string> ints, bools;                    // all data
  std::vector<std::string> exported_ints, exported_bools;  // readable by compound priorities
  std::vector<std::string> clocks;
  std::vector<AtomPort> ports;
};

/// A port a connector of the compound under construction may bind.
struct Offer {
  std::string ref;  // as written in a binding: a0.p1, s0.x2, c3.top
  int type = kSig;
  std::vector<std::string> components;  // components it reaches: a connector binds each once
  bool must_bind = false;               // a connector's exported port: must be bound
  bool used = false;
};

/// Define shapes of a connector type: `p0 p1`, `p0' p1 p2`, `p0' p1'`.
enum class Define { kRendezvous, kBroadcast, kAllTriggers };

/// A connector instance made in a compound, as priorities need to name it.
struct MadeConnector {
  std::string name;
  std::vector<std::string> refs;  // bound ports, in parameter order
  Define define = Define::kRendezvous;
};

/// A compound type under construction.
struct Scope {
  std::vector<Offer> offers;
  std::vector<MadeConnector> top_level;              // connectors that no connector binds
  std::vector<std::string> guard_ints, guard_bools;  // exported data of its components
  std::ostringstream body;
};

/// What a sub-compound type exports.
struct SubType {
  std::string name;
  std::vector<Offer> exports;  // refs are the exported names
  std::vector<std::string> data_ints, data_bools;
};

class Generator {
 public:
  explicit Generator(const RandomModelOptions& options) : options_(options), rng_(options.seed) {}

  std::string package(const std::string& name) {
    const int type_count = uniform(1, std::clamp(options_.atoms, 1, 3));
    for (int i = 0; i < type_count; ++i) make_atom_type(i);

    int sub_instances = 0;
    if (options_.hierarchy && options_.atoms >= 3) {
      sub_instances = uniform(1, std::max(1, (options_.atoms - 1) / 3));
    }
    std::vector<SubType> subs;
    const int sub_types = sub_instances == 0 ? 0 : uniform(1, std::min(2, sub_instances));
    for (int i = 0; i < sub_types; ++i) subs.push_back(make_sub_type(i));
    make_root(subs, sub_instances, options_.atoms - 2 * sub_instances);

    std::ostringstream out;
    out << "// Random model (seed " << options_.seed << ", " << options_.atoms << " atoms"
        << (options_.clocks ? ", timed" : "") << ").\n"
        << "package " << name << "\n"
        << "  port type Sig()\n";
    if (options_.data) {
      out << "  port type IntPort(int v)\n"
          << "  port type BoolPort(bool b)\n"
          << "  port type PairPort(int v, bool b)\n";
    }
    out << "\n" << connector_types_.str() << atom_types_text_.str() << compounds_.str() << "end\n";
    return out.str();
  }

 private:
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(int percent) { return uniform(0, 99) < percent; }
  template <class T>
  const T& one_of(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(uniform(0, static_cast<int>(items.size()) - 1))];
  }
  std::string number(int lo, int hi) { return std::to_string(uniform(lo, hi)); }

  /// A clock-free condition over int data `ints` (never empty) and bool data `bools`.
  std::string data_guard(const std::vector<std::string>& ints,
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

  /// One or two statements keeping int data in [0, 7).
  std::string data_action(const std::vector<std::string>& ints,
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

  std::string clock_guard(const AtomType& type) {
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

  /// Writes one transition; `label` empty makes it an unlabelled internal one (no clocks then,
  /// as the language requires), `guard` is its clock-free data condition (may be empty).
  void transition(std::ostream& out, const AtomType& type, const std::string& label,
                  const std::vector<std::string>& from, const std::vector<std::string>& to,
                  const std::string& guard) {
    const bool internal = label.empty();
    const bool timed = !internal && !type.clocks.empty();
    std::vector<std::string> conditions;
    if (timed && chance(50)) conditions.push_back(clock_guard(type));
    if (!guard.empty()) conditions.push_back(conditions.empty() ? guard : "(" + guard + ")");
    out << "    " << (internal ? "internal" : "on " + label) << " from " << join(from, ", ")
        << " to " << join(to, ", ");
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

  void make_atom_type(int index) {
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
      if (options_.data)
        port.type = type.bools.empty() ? uniform(kSig, kInt) : uniform(kSig, kPair);
      port.region = aux_places > 0 && i > 0 && chance(30) ? 1 : 0;
      std::vector<std::string> args;
      if (has_int(port.type)) args.push_back(one_of(type.ints));
      if (has_bool(port.type)) args.push_back(one_of(type.bools));
      out << "    " << (port.exported ? "export port " : "port ") << kPortTypeNames[port.type]
          << " " << port.name << "(" << join(args, ", ") << ")\n";
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

  /// Declares component `name` of a random atom type in `scope`, offering its exported ports.
  void add_atom(Scope& scope, const std::string& name) {
    const AtomType& type = one_of(atom_types_);
    scope.body << "    component " << type.name << " " << name << "("
               << (options_.data ? number(0, 4) : "") << ")\n";
    for (const AtomPort& port : type.ports) {
      if (!port.exported) continue;
      scope.offers.push_back(Offer{name + "." + port.name, port.type, {name}, false});
    }
    for (const std::string& x : type.exported_ints) scope.guard_ints.push_back(name + "." + x);
    for (const std::string& b : type.exported_bools) scope.guard_bools.push_back(name + "." + b);
  }

  /// The interactions (lists of port indices) a define allows.
  static std::vector<std::vector<int>> interactions(Define define, int ports) {
    std::vector<std::vector<int>> all;
    for (int mask = 1; mask < (1 << ports); ++mask) {
      if (define == Define::kRendezvous && mask != (1 << ports) - 1) continue;
      if (define == Define::kBroadcast && (mask & 1) == 0) continue;
      std::vector<int> members;
      for (int i = 0; i < ports; ++i) {
        if (mask & (1 << i)) members.push_back(i);
      }
      all.push_back(members);
    }
    return all;
  }

  /// Adds one connector over unused offers of `scope` (those that must be bound first).
  /// With `allow_export` it may export a port that a later connector binds. Returns false when
  /// no offer is left.
  bool add_connector(Scope& scope, bool allow_export) {
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < scope.offers.size(); ++i) {
      if (!scope.offers[i].used) candidates.push_back(i);
    }
    if (candidates.empty()) return false;
    std::shuffle(candidates.begin(), candidates.end(), rng_);
    std::stable_partition(candidates.begin(), candidates.end(),
                          [&](std::size_t i) { return scope.offers[i].must_bind; });
    const int arity = one_of(std::vector<int>{1, 2, 2, 2, 3, 3, 4});
    std::vector<std::size_t> chosen;
    std::set<std::string> components;
    for (std::size_t i : candidates) {
      if (static_cast<int>(chosen.size()) == arity) break;
      const Offer& offer = scope.offers[i];
      if (std::any_of(offer.components.begin(), offer.components.end(),
                      [&](const std::string& a) { return components.count(a) > 0; })) {
        continue;
      }
      chosen.push_back(i);
      components.insert(offer.components.begin(), offer.components.end());
    }
    const int ports = static_cast<int>(chosen.size());

    Define define = Define::kRendezvous;
    if (ports >= 2) {
      const int shape = uniform(0, 99);
      if (shape >= 45) define = Define::kBroadcast;
      if (shape >= 85 && ports <= 3) define = Define::kAllTriggers;
    }
    const bool exports = allow_export && options_.hierarchy && chance(30) &&
                         (define == Define::kRendezvous || ports <= 3);
    const bool export_data = exports && options_.data && chance(60);

    const std::string id = std::to_string(connector_count_++);
    const std::string type_name = "K" + id, name = "c" + id;
    std::ostringstream text;
    std::vector<std::string> params, int_refs_all, bool_refs_all;
    for (int i = 0; i < ports; ++i) {
      const Offer& offer = scope.offers[chosen[static_cast<std::size_t>(i)]];
      params.push_back(std::string(kPortTypeNames[offer.type]) + " p" + std::to_string(i));
    }
    text << "  connector type " << type_name << "(" << join(params, ", ") << ")\n";
    const bool uses_tmp = options_.data && chance(30);
    if (uses_tmp) text << "    data int tmp\n";
    if (export_data) text << "    data int d\n";
    if (exports) {
      text << "    export port " << (export_data ? "IntPort top(d)" : "Sig top()") << "\n";
    }
    text << "    define";
    for (int i = 0; i < ports; ++i) {
      const bool trigger =
          (define == Define::kBroadcast && i == 0) || define == Define::kAllTriggers;
      text << " p" << i << (trigger ? "'" : "");
    }
    text << "\n";

    // `on` clauses: guards over port data, up (when data are exported) and down transfers.
    std::vector<std::vector<int>> allowed = interactions(define, ports);
    std::shuffle(allowed.begin(), allowed.end(), rng_);
    const std::size_t described =
        export_data ? allowed.size()
                    : std::min<std::size_t>(allowed.size(), options_.data ? uniform(0, 2) : 0);
    for (std::size_t k = 0; k < described; ++k) {
      std::vector<std::string> names, ints, bools;
      for (int i : allowed[k]) {
        const std::string port = "p" + std::to_string(i);
        const int type = scope.offers[chosen[static_cast<std::size_t>(i)]].type;
        names.push_back(port);
        if (has_int(type)) ints.push_back(port + ".v");
        if (has_bool(type)) bools.push_back(port + ".b");
      }
      text << "    on " << join(names, " ");
      if (!ints.empty() && chance(50)) text << " provided (" << data_guard(ints, bools) << ")";
      if (export_data) {
        text << " up { d = " << (ints.empty() ? number(0, 4) : "(" + join(ints, " + ") + ") % 7")
             << "; }";
      }
      std::vector<std::string> down;
      if (!ints.empty() && chance(60)) {
        const std::string& target = one_of(ints);
        if (uses_tmp && ints.size() >= 2 && target != ints[0]) {
          down.push_back("tmp = " + ints[0] + "; " + ints[0] + " = " + target + "; " + target +
                         " = tmp;");
        } else {
          down.push_back(target + " = (" + one_of(ints) + " + 1) % 5;");
        }
      }
      if (export_data && !ints.empty() && chance(50)) down.push_back(one_of(ints) + " = d % 5;");
      if (!bools.empty() && chance(30))
        down.push_back(one_of(bools) + " = !" + one_of(bools) + ";");
      if (!down.empty()) text << " down { " << join(down, " ") << " }";
      text << "\n";
    }
    text << "  end\n\n";
    connector_types_ << text.str();

    MadeConnector made{name, {}, define};
    for (std::size_t i : chosen) {
      scope.offers[i].used = true;
      made.refs.push_back(scope.offers[i].ref);
    }
    scope.body << "    connector " << type_name << " " << name << "(" << join(made.refs, ", ")
               << ")\n";
    if (exports) {
      scope.offers.push_back(Offer{name + ".top", export_data ? kInt : kSig,
                                   std::vector<std::string>(components.begin(), components.end()),
                                   true});
    } else {
      scope.top_level.push_back(std::move(made));
    }
    return true;
  }

  /// Binds every exported connector port left in `scope`, with connectors exporting nothing.
  void bind_pending(Scope& scope) {
    while (std::any_of(scope.offers.begin(), scope.offers.end(),
                       [](const Offer& o) { return o.must_bind && !o.used; })) {
      add_connector(scope, false);
    }
  }

  /// An interaction pattern of a priority rule: `c:*` or one interaction its define allows.
  std::string pattern(const MadeConnector& connector) {
    if (chance(60)) return connector.name + ":*";
    std::vector<std::string> refs;
    switch (connector.define) {
      case Define::kRendezvous:
        refs = connector.refs;
        break;
      case Define::kBroadcast:
        refs.push_back(connector.refs[0]);
        for (std::size_t i = 1; i < connector.refs.size(); ++i) {
          if (chance(50)) refs.push_back(connector.refs[i]);
        }
        break;
      case Define::kAllTriggers:
        for (const std::string& ref : connector.refs) {
          if (chance(50)) refs.push_back(ref);
        }
        if (refs.empty()) refs.push_back(one_of(connector.refs));
        break;
    }
    return connector.name + ":" + join(refs, ",");
  }

  /// Priority rules of `scope`, each ranking a connector below a later one (no cycle).
  void add_priorities(Scope& scope) {
    const int top = static_cast<int>(scope.top_level.size());
    if (!options_.priorities || top < 2) return;
    const int rules = uniform(0, std::min(3, top - 1));
    std::set<std::pair<int, int>> made;
    int rule_count = 0;
    for (int r = 0; r < rules; ++r) {
      const int low = uniform(0, top - 2), high = uniform(low + 1, top - 1);
      if (!made.insert({low, high}).second) continue;
      scope.body << "    priority r" << rule_count++ << " "
                 << pattern(scope.top_level[static_cast<std::size_t>(low)]) << " < "
                 << pattern(scope.top_level[static_cast<std::size_t>(high)]);
      if (!scope.guard_ints.empty() && chance(40)) {
        scope.body << " provided (" << data_guard(scope.guard_ints, scope.guard_bools) << ")";
      }
      scope.body << "\n";
    }
    if (chance(20)) {
      scope.body << "    priority r" << rule_count << " *:* < " << scope.top_level.back().name
                 << ":*\n";
    }
  }

  SubType make_sub_type(int index) {
    SubType sub;
    sub.name = "S" + std::to_string(index);
    Scope scope;
    add_atom(scope, "a0");
    add_atom(scope, "a1");
    const int connectors = uniform(0, 2);
    for (int i = 0; i < connectors && add_connector(scope, true); ++i) {
    }
    add_priorities(scope);
    int exported = 0;
    for (Offer& offer : scope.offers) {
      if (offer.used || !(offer.must_bind || chance(75))) continue;
      const std::string as = "x" + std::to_string(exported++);
      scope.body << "    export port " << offer.ref << " as " << as << "\n";
      sub.exports.push_back(Offer{as, offer.type, offer.components, offer.must_bind, false});
    }
    for (std::size_t i = 0; i < scope.guard_ints.size(); ++i) {
      if (i > 0 && chance(50)) continue;
      const std::string as = "d" + std::to_string(sub.data_ints.size());
      scope.body << "    export data " << scope.guard_ints[i] << " as " << as << "\n";
      sub.data_ints.push_back(as);
    }
    for (const std::string& b : scope.guard_bools) {
      if (chance(50)) continue;
      const std::string as = "e" + std::to_string(sub.data_bools.size());
      scope.body << "    export data " << b << " as " << as << "\n";
      sub.data_bools.push_back(as);
    }
    compounds_ << "  compound type " << sub.name << "()\n" << scope.body.str() << "  end\n\n";
    return sub;
  }

  void make_root(const std::vector<SubType>& subs, int sub_instances, int root_atoms) {
    Scope scope;
    for (int i = 0; i < root_atoms; ++i) {
      const std::string name = "a" + std::to_string(i);
      add_atom(scope, name);
    }
    for (int i = 0; i < sub_instances; ++i) {
      const SubType& sub = one_of(subs);
      const std::string name = "s" + std::to_string(i);
      scope.body << "    component " << sub.name << " " << name << "()\n";
      for (const Offer& port : sub.exports) {
        scope.offers.push_back(Offer{name + "." + port.ref, port.type, {name}, port.must_bind});
      }
      for (const std::string& x : sub.data_ints) scope.guard_ints.push_back(name + "." + x);
      for (const std::string& b : sub.data_bools) scope.guard_bools.push_back(name + "." + b);
    }
    for (int i = 0; i < options_.connectors && add_connector(scope, true); ++i) {
    }
    bind_pending(scope);
    add_priorities(scope);
    compounds_ << "  compound type Root()\n" << scope.body.str() << "  end\n";
  }

  RandomModelOptions options_;
  std::mt19937_64 rng_;
  std::vector<AtomType> atom_types_;
  std::ostringstream atom_types_text_, connector_types_, compounds_;
  int connector_count_ = 0;
};

}  // namespace

std::string random_bip_package(const RandomModelOptions& options, const std::string& package_name) {
  return Generator(options).package(package_name);
}

}  // namespace smcbip::tests
