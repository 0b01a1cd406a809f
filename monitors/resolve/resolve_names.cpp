// Name resolution and typing of property files against a model's IR (see resolve_names.h).
#include "monitors/resolve/resolve_names.h"

#include <map>
#include <optional>
#include <string>
#include <utility>

namespace smcbip::monitors {

namespace {

using bipc::ir::Index;
using bipc::ir::System;

std::optional<Index> find_in(const std::vector<std::string>& names, const std::string& name) {
  for (Index i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  return std::nullopt;
}

template <class T>
std::optional<Index> find_named(const std::vector<T>& items, const std::string& name) {
  for (Index i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return i;
  }
  return std::nullopt;
}

class Resolver {
 public:
  Resolver(const PropertyFile& file, const System& system, bipc::Diagnostics& diagnostics)
      : system_(system), diagnostics_(diagnostics) {
    for (Index i = 0; i < system.atoms.size(); ++i) atoms_.emplace(system.atoms[i].path, i);
    for (Index i = 0; i < system.connectors.size(); ++i) {
      connectors_.emplace(system.connectors[i].path, i);
    }
    for (Index i = 0; i < system.compounds.size(); ++i) {
      compounds_.emplace(system.compounds[i].path, i);
    }
    for (Index i = 0; i < file.declarations.size(); ++i) {
      constants_.emplace(file.declarations[i].name, i);
    }
  }

  void formula(Formula& f) {
    if (f.atom) condition(*f.atom, "an atomic predicate");
    for (auto& operand : f.operands) formula(*operand);
  }

  /// Resolves and types `e`; false when it (or a part) does not resolve or fit (reported).
  bool expression(Expr& e) {
    bool ok = true;
    for (auto& operand : e.operands) ok = expression(*operand) && ok;
    if (!ok) return false;
    switch (e.kind) {
      case Expr::Kind::Number:
        return true;
      case Expr::Kind::Bool:
        e.is_bool = true;
        return true;
      case Expr::Kind::Name:
        return name(e);
      case Expr::Kind::Fired:
        e.is_bool = true;
        return fired(e);
      case Expr::Kind::Equal:
      case Expr::Kind::NotEqual:
        e.is_bool = true;
        if (e.operands[0]->is_bool != e.operands[1]->is_bool) {
          return fail(e.at, "'" + to_string(e) + "' compares a condition with a number");
        }
        return true;
      case Expr::Kind::Less:
      case Expr::Kind::LessEqual:
      case Expr::Kind::Greater:
      case Expr::Kind::GreaterEqual:
        e.is_bool = true;
        return numbers(e);
      case Expr::Kind::Multiply:
      case Expr::Kind::Divide:
      case Expr::Kind::Modulo:
        return numbers(e) && linear(e);
      default:  // arithmetic and abs, min, max
        return numbers(e);
    }
  }

  /// Whether the model has clocks: without, time bounds and `time` measure nothing it shows.
  bool timed_model() const {
    for (const bipc::ir::AtomInstance& atom : system_.atoms) {
      if (!system_.atom_types[atom.type].clocks.empty()) return true;
    }
    return false;
  }

  void untimed_bound(const Bound& b) {
    if (b.kind != Bound::Kind::Time) return;
    fail(b.high.at,
         "the model has no clocks, so a time bound measures nothing it shows: bound "
         "by steps instead (F{k} phi or F[#<=k] phi, Pr[#<=K](...))");
  }
  void untimed_formula(const Formula& f) {
    untimed_bound(f.bound);
    if (f.atom) untimed_expression(*f.atom);
    for (const auto& operand : f.operands) untimed_formula(*operand);
  }
  void untimed_expression(const Expr& e) {
    if (e.kind == Expr::Kind::Name && e.reference.kind == Reference::Kind::Time) {
      fail(e.at,
           "the model has no clocks, so 'time' measures nothing it shows: count steps "
           "with a step bound instead (F{k} phi)");
    }
    for (const auto& operand : e.operands) untimed_expression(*operand);
  }

  /// A condition: a predicate or a boolean term.
  void condition(Expr& e, const std::string& what) {
    if (expression(e) && !e.is_bool) {
      fail(e.at, what + " must be a condition, but '" + to_string(e) + "' is a number");
    }
  }

  void number(Expr& e, const std::string& what) {
    if (expression(e) && e.is_bool) {
      fail(e.at, what + " must be a number, but '" + to_string(e) + "' is a condition");
    }
  }

 private:
  bool numbers(const Expr& e) {
    for (const auto& operand : e.operands) {
      if (operand->is_bool) {
        return fail(operand->at, "'" + to_string(*operand) + "' is a condition where '" +
                                     to_string(e) + "' needs a number");
      }
    }
    return true;
  }

  /// The path without the root's name, if it leads.
  std::string below_root(const std::string& path) const {
    const std::string root = system_.root_name + ".";
    return path.compare(0, root.size(), root) == 0 ? path.substr(root.size()) : path;
  }

  bool name(Expr& e) {
    if (is_builtin(e.reference)) return true;
    const std::string path = below_root(e.path);
    const std::size_t dot = path.rfind('.');
    if (dot == std::string::npos) {
      const auto constant = constants_.find(path);
      if (constant == constants_.end()) {
        return fail(e.at, "unknown name '" + e.path +
                              "': expected atom.data, atom.place or atom.clock, or a declared "
                              "constant or parameter");
      }
      e.reference = {Reference::Kind::Constant, 0, constant->second};
      return true;
    }
    const std::string owner = path.substr(0, dot), member = path.substr(dot + 1);
    if (const auto atom = atoms_.find(owner); atom != atoms_.end()) {
      return atom_member(e, atom->second, member);
    }
    if (const auto compound = compounds_.find(owner); compound != compounds_.end()) {
      const auto& exported = system_.compounds[compound->second].exported_data;
      if (const auto data = exported.find(member); data != exported.end()) {
        return data_reference(e, data->second.first, data->second.second);
      }
      return fail(e.at, "compound '" + owner + "' exports no data '" + member + "'");
    }
    return fail(e.at, "unknown atom '" + owner + "' in '" + e.path + "'");
  }

  bool atom_member(Expr& e, Index atom, const std::string& member) {
    const bipc::ir::AtomType& type = system_.atom_types[system_.atoms[atom].type];
    const std::optional<Index> place = find_in(type.places, member);
    const std::optional<Index> data = find_named(type.data, member);
    const std::optional<Index> clock = find_named(type.clocks, member);
    if (place && (data || clock)) {
      return fail(e.at, "'" + e.path + "' is ambiguous: '" + member +
                            "' is both a place and a variable of atom '" +
                            system_.atoms[atom].path + "'");
    }
    if (place) {
      e.reference = {Reference::Kind::Place, atom, *place};
      e.is_bool = true;
      return true;
    }
    if (data) return data_reference(e, atom, *data);
    if (clock) {
      e.reference = {Reference::Kind::Clock, atom, *clock};
      return true;
    }
    return fail(e.at, "atom '" + system_.atoms[atom].path + "' (" + type.name +
                          ") has no data, place or clock '" + member + "'");
  }

  bool data_reference(Expr& e, Index atom, Index slot) {
    const bipc::ir::AtomType& type = system_.atom_types[system_.atoms[atom].type];
    const bipc::ir::ValueKind kind = type.data[slot].type.kind;
    if (kind != bipc::ir::ValueKind::Bool && kind != bipc::ir::ValueKind::Int &&
        kind != bipc::ir::ValueKind::Float) {
      return fail(e.at, "'" + e.path +
                            "' is neither a number nor a boolean, which predicates "
                            "cannot compare");
    }
    e.reference = {Reference::Kind::Data, atom, slot};
    e.is_bool = kind == bipc::ir::ValueKind::Bool;
    return true;
  }

  bool fired(Expr& e) {
    const std::string path = below_root(e.path);
    if (const auto connector = connectors_.find(path); connector != connectors_.end()) {
      e.reference = {Reference::Kind::Connector, 0, connector->second};
      return true;
    }
    const std::size_t dot = path.rfind('.');
    if (dot != std::string::npos) {
      if (const auto atom = atoms_.find(path.substr(0, dot)); atom != atoms_.end()) {
        const auto& ports = system_.atom_types[system_.atoms[atom->second].type].ports;
        if (const std::optional<Index> port = find_named(ports, path.substr(dot + 1))) {
          e.reference = {Reference::Kind::InternalPort, atom->second, *port};
          return true;
        }
      }
    }
    return fail(e.at, "fired(" + e.path + "): no connector or atom port of that name");
  }

  /// Whether `e` grows with time between steps: it reads a clock or the global time.
  static bool grows(const Expr& e) {
    if (e.kind == Expr::Kind::Name) {
      return e.reference.kind == Reference::Kind::Clock ||
             e.reference.kind == Reference::Kind::Time;
    }
    for (const auto& operand : e.operands) {
      if (grows(*operand)) return true;
    }
    return false;
  }

  /// Clocks are read continuously, so what reads them must be linear in them: a product of two
  /// clocks, a division by a clock or a remainder of one would change truth between the
  /// crossings the monitor computes.
  bool linear(const Expr& e) {
    const bool left = grows(*e.operands[0]), right = grows(*e.operands[1]);
    if (e.kind == Expr::Kind::Multiply && left && right) {
      return fail(e.at, "'" + to_string(e) +
                            "' multiplies two values that grow with time "
                            "(clocks or time); predicates over clocks must be linear in them");
    }
    if (e.kind == Expr::Kind::Divide && right) {
      return fail(e.at, "'" + to_string(e) +
                            "' divides by a value that grows with time "
                            "(a clock or time); predicates over clocks must be linear in them");
    }
    if (e.kind == Expr::Kind::Modulo && (left || right)) {
      return fail(e.at,
                  "'" + to_string(e) +
                      "' takes a remainder of a value that grows with "
                      "time (a clock or time); predicates over clocks must be linear in them");
    }
    return true;
  }

  bool fail(bipc::Location at, const std::string& message) {
    diagnostics_.error(at, message);
    return false;
  }

  const System& system_;
  bipc::Diagnostics& diagnostics_;
  std::map<std::string, Index> atoms_, connectors_, compounds_, constants_;
};

}  // namespace

void resolve_names(PropertyFile& file, const bipc::ir::System& system,
                   bipc::Diagnostics& diagnostics) {
  Resolver resolver(file, system, diagnostics);
  const bool timed = resolver.timed_model();
  for (Query& q : file.queries) {
    if (q.formula) resolver.formula(*q.formula);
    if (q.other) resolver.formula(*q.other);
    if (q.observed && q.observe == Observation::Count) {
      resolver.condition(*q.observed, "what count: counts");
    } else if (q.observed) {
      resolver.number(*q.observed, "the observed expression");
    }
    for (auto& e : q.series) resolver.expression(*e);
    if (timed) continue;
    resolver.untimed_bound(q.run);
    resolver.untimed_bound(q.other_run);
    if (q.formula) resolver.untimed_formula(*q.formula);
    if (q.other) resolver.untimed_formula(*q.other);
    if (q.observed) resolver.untimed_expression(*q.observed);
    for (const auto& e : q.series) resolver.untimed_expression(*e);
  }
}

}  // namespace smcbip::monitors
