// The random model generator's internals, shared by its three parts: random_model.cpp (the
// package and its compounds), random_model_atoms.cpp (atom types: places, transitions, data and
// clocks) and random_model_connectors.cpp (components, connectors and priority rules).
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "random_model.h"

namespace smcbip::tests::random_model_detail {

/// The port types every package declares; an atom port binds data of the matching types.
enum PortType { kSig = 0, kInt = 1, kBool = 2, kPair = 3 };
inline constexpr const char* kPortTypeNames[] = {"Sig", "IntPort", "BoolPort", "PairPort"};

inline bool has_int(int type) { return type == kInt || type == kPair; }
inline bool has_bool(int type) { return type == kBool || type == kPair; }

/// The items separated by `separator`.
inline std::string join(const std::vector<std::string>& items, const std::string& separator) {
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
  bool stochastic = false;  // carries a @stochastic annotation
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
  bool stochastic = false;  // fires a @stochastic port: a connector binds at most one such
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

/// Draws one package from one random stream, so the seed alone fixes the text (the order of the
/// draws, not the file a drawing function lives in, is what reproducing a seed depends on).
class Generator {
 public:
  explicit Generator(const RandomModelOptions& options) : options_(options), rng_(options.seed) {}

  /// The package text, named `name`, with its root compound `Root()`.
  std::string package(const std::string& name);

 private:
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(int percent) { return uniform(0, 99) < percent; }
  template <class T>
  const T& one_of(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(uniform(0, static_cast<int>(items.size()) - 1))];
  }
  std::string number(int lo, int hi) { return std::to_string(uniform(lo, hi)); }

  // Atom types (random_model_atoms.cpp).

  /// A clock-free condition over int data `ints` (never empty) and bool data `bools`.
  std::string data_guard(const std::vector<std::string>& ints,
                         const std::vector<std::string>& bools);
  /// One or two statements keeping int data in [0, 7).
  std::string data_action(const std::vector<std::string>& ints,
                          const std::vector<std::string>& bools);
  /// A guard over one of the clocks of `type` (which has some).
  std::string clock_guard(const AtomType& type);
  /// Writes one transition; `label` empty makes it an unlabelled internal one (no clocks then,
  /// as the language requires), `guard` is its clock-free data condition (may be empty).
  void transition(std::ostream& out, const AtomType& type, const std::string& label,
                  const std::vector<std::string>& from, const std::vector<std::string>& to,
                  const std::string& guard);
  /// Draws atom type `A<index>`, appends its text and records it in atom_types_.
  void make_atom_type(int index);

  // Architecture (random_model_connectors.cpp).

  /// Declares component `name` of a random atom type in `scope`, offering its exported ports.
  void add_atom(Scope& scope, const std::string& name);
  /// The interactions (lists of port indices) a define allows.
  static std::vector<std::vector<int>> interactions(Define define, int ports);
  /// Adds one connector over unused offers of `scope` (those that must be bound first).
  /// With `allow_export` it may export a port that a later connector binds. Returns false when
  /// no offer is left.
  bool add_connector(Scope& scope, bool allow_export);
  /// Binds every exported connector port left in `scope`, with connectors exporting nothing.
  void bind_pending(Scope& scope);
  /// An interaction pattern of a priority rule: `c:*` or one interaction its define allows.
  std::string pattern(const MadeConnector& connector);
  /// Priority rules of `scope`, each ranking a connector below a later one (no cycle).
  void add_priorities(Scope& scope);

  // Compounds (random_model.cpp).

  /// Draws sub-compound type `S<index>` over two atoms, with what it exports.
  SubType make_sub_type(int index);
  /// The root compound: `root_atoms` atoms, `sub_instances` instances of `subs`, connectors.
  void make_root(const std::vector<SubType>& subs, int sub_instances, int root_atoms);

  RandomModelOptions options_;
  std::mt19937_64 rng_;
  std::vector<AtomType> atom_types_;
  std::ostringstream atom_types_text_, connector_types_, compounds_;
  int connector_count_ = 0;
};

}  // namespace smcbip::tests::random_model_detail
