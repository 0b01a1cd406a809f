// The pieces of the nominal package while it is assembled: its declarations (each once), the
// members of `Syst()` and the report lines.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/translate/package.h"
#include "taste2bip/translate/signature.h"
#include "taste2bip/writer/wrappers.h"

namespace smcbip::taste2bip::detail {

/// A declaration written once however many users it has, in the order first needed.
class OnceList {
 public:
  /// False when `key` was already added.
  bool add(const std::string& key, std::string text);
  std::string text() const;

 private:
  std::set<std::string> keys_;
  std::vector<std::string> texts_;
};

struct PackageParts {
  OnceList extern_types, port_types, connector_types, atom_types;
  std::vector<std::string> function_components, components, connectors;
  std::vector<std::string> report;
};

/// Milliseconds of the view as the integer BIP takes, rounded up (a note in the report when
/// the view's value was not whole).
std::int64_t whole_milliseconds(double ms, const std::string& what, PackageParts& parts);

/// Declares the port type for these data types (names a0, a1, ...) and returns its name.
std::string use_port_type(const std::vector<std::string>& types, PackageParts& parts);

/// Declares the connector type joining a sender of port type `types`, its receiver (the data
/// copied from the first to the second) and `extra` ports of type Port (no data), and returns
/// its name. extra == 0, types empty: `Sync`.
std::string use_connector_type(const std::vector<std::string>& types, int extra,
                               PackageParts& parts);
/// `Alone_<PT>`: a connector of one port, for a required interface connected to nothing.
std::string use_lone_connector_type(const std::vector<std::string>& types, PackageParts& parts);

/// The wrappers and connectors of the provided interfaces of `function`, and the connectors of
/// its required ones (to the provided interfaces of `functions` they reach in `view`).
void connect_function(const InterfaceView& view, const std::vector<FunctionSignature>& functions,
                      std::size_t index, Wcet wcet, PackageParts& parts, bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip::detail
