// Random valid BIP2 packages: atom types, sub-compounds, connectors and priorities drawn by seed.
// The package and its compounds; atom types and connectors are drawn in the other two parts.
#include "random_model.h"

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "random_model_generator.h"

namespace smcbip::tests {

namespace random_model_detail {

std::string Generator::package(const std::string& name) {
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

namespace {

/// Ports left unbound are never offered, which the models mean: the annotation keeps the front
/// end from warning about them (the Verimag front end's name for that warning).
const char* unbound_ports_allowed(bool leaves_unbound) {
  return leaves_unbound ? "  @SuppressWarning(unboundcomponentport)\n" : "";
}

}  // namespace

SubType Generator::make_sub_type(int index) {
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
  bool leaves_unbound = false;
  for (Offer& offer : scope.offers) {
    if (offer.used) continue;
    if (!(offer.must_bind || chance(75))) {
      leaves_unbound = true;
      continue;
    }
    const std::string as = "x" + std::to_string(exported++);
    scope.body << "    export port " << offer.ref << " as " << as << "\n";
    sub.exports.push_back(
        Offer{as, offer.type, offer.components, offer.must_bind, false, offer.stochastic});
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
  compounds_ << unbound_ports_allowed(leaves_unbound) << "  compound type " << sub.name << "()\n"
             << scope.body.str() << "  end\n\n";
  return sub;
}

void Generator::make_root(const std::vector<SubType>& subs, int sub_instances, int root_atoms) {
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
      scope.offers.push_back(
          Offer{name + "." + port.ref, port.type, {name}, port.must_bind, false, port.stochastic});
    }
    for (const std::string& x : sub.data_ints) scope.guard_ints.push_back(name + "." + x);
    for (const std::string& b : sub.data_bools) scope.guard_bools.push_back(name + "." + b);
  }
  for (int i = 0; i < options_.connectors && add_connector(scope, true); ++i) {
  }
  bind_pending(scope);
  add_priorities(scope);
  const bool leaves_unbound = std::any_of(scope.offers.begin(), scope.offers.end(),
                                          [](const Offer& offer) { return !offer.used; });
  compounds_ << unbound_ports_allowed(leaves_unbound) << "  compound type Root()\n"
             << scope.body.str() << "  end\n";
}

}  // namespace random_model_detail

std::string random_bip_package(const RandomModelOptions& options, const std::string& package_name) {
  return random_model_detail::Generator(options).package(package_name);
}

}  // namespace smcbip::tests
