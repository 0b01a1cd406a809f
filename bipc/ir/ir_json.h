// A readable JSON view of the IR (`bipc ir --json`), for people, tests and scripts.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// The whole system: types, instances by path, bound ports by `path.port` names, priorities,
/// and code as arrays of instruction texts. Deterministic: the same System gives the same text.
nlohmann::json to_json(const System& system);

/// One instruction as text: "push.int 3", "load atom.data[2]", "lt.int", "call min/2",
/// "jump_if_false 7"... Loads and stores of another instance's data name it after a `;`.
std::string instruction_text(const Instr& instr, const System& system);

/// A bound port by name: `path.port` for an atom port, `path.export` for a connector's export.
std::string port_ref_name(const PortRef& ref, const System& system);

}  // namespace smcbip::bipc::ir
