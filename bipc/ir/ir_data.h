// A full-fidelity, deterministic encoding of the IR (JSON values, CBOR bytes) and its decoder.
//
// Unlike ir_json.h, which is a view for people, this encoding keeps every field of System and
// of everything it holds, so that from_data(to_data(s)) is s again field by field. Generated
// projects embed it, and model_hash.h hashes it.
//
// Layout: each struct of ir.h is a JSON object whose keys are the C++ field names, except
//  - an Instr, the bulk of the data, which is an array [op, kind, scope, arg, index, imm, site]
//    where imm is the union member the op reads: a boolean for push_bool, a float for
//    push_float, an integer (imm.i) for every other op;
//  - a Location, which is an array [file, line, column];
//  - pairs (typed parameters, connector ports, annotation parameters, exported data), which are
//    two-element arrays;
//  - std::optional fields, which are null when empty;
//  - CompoundInstance::exported_ports and exported_data, which are JSON objects keyed by name.
// Enumerations are written by name in snake_case ("push_int", "atom_data", "millisecond"), every
// ir::Index as an unsigned integer or null for kNone. Doubles are JSON floating-point numbers
// when finite; infinities and NaNs (a float literal may fold to one, and a @stochastic
// parameter may read "inf") are the string "f64:" followed by the 16 lowercase hex digits of
// their IEEE-754 bits, since JSON text has no spelling for them and CBOR would drop a NaN's
// payload. The top-level object also carries "format": "smcbip-ir" and "version": 2
// (version 2 added Instr::site, System::sites and System::source_files).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// The encoding's version, in the "version" field; from_data accepts only this one.
inline constexpr int kIrDataVersion = 2;

/// Malformed input to from_data or from_bytes. `message` names the offending field by its path
/// from the top, e.g. `atom_types[2].transitions[0].guard.instrs[3][4]: index 7 out of range`.
struct IrDataError {
  std::string message;
};

/// Every field of `system`, as described at the top of this file. Deterministic: the same
/// System always gives an equal value (and the same bytes once serialised), since objects keep
/// their keys sorted and no unordered container is visited.
nlohmann::json to_data(const System& system);

/// The inverse of to_data. Throws IrDataError unless `data` is what to_data could have
/// written, as far as these checks go:
///  - every field is present, has the right JSON type, and no object has an unknown key;
///  - integers fit their C++ type; enumeration names and "f64:" strings are known spellings;
///  - "format" is "smcbip-ir" and "version" is kIrDataVersion;
///  - every index an engine or generator would follow is in range: types of instances, parents
///    and children, port types, data slots, places, ports, clocks, extern types, functions,
///    strings and sites named by instructions, PortRefs, priority sides, exported data,
///    connectors' bound_by; kNone only where ir.h allows it (internal transitions, wildcards, the root's
///    parent, non-extern data types, ...);
///  - per instruction, the slot a load or store names exists in its code's context (atom code:
///    atom data, parameters and clocks; connector code: connector data and port parameters;
///    compound priority guards: other instances' data); jump targets are at most the code's
///    length; Code::id is below code_count;
///  - per instance, as many parameters (atoms) or bindings (connectors: bound, bound_names and
///    bound_through_compound) as its type has;
///  - define trees are at most kMaxDefineDepth deep.
/// Not checked: that code is well typed or keeps its stack balanced, that a call passes as
/// many arguments as the function takes, that names and paths are unique or consistent, and
/// that strings are UTF-8 (the front end passes on string literals that are not, and they
/// must round-trip).
System from_data(const nlohmann::json& data);

/// The deepest define tree from_data accepts (the parser allows 256 levels of nesting).
inline constexpr std::size_t kMaxDefineDepth = 1024;

/// nlohmann::json::to_cbor(to_data(system)): definite lengths, sorted map keys, deterministic.
std::vector<std::uint8_t> to_bytes(const System& system);

/// The inverse of to_bytes: CBOR that is malformed, truncated, followed by extra bytes or
/// nested deeper than from_data could ever need throws IrDataError, as does any failure of
/// from_data on the decoded value.
System from_bytes(std::span<const std::uint8_t> bytes);

}  // namespace smcbip::bipc::ir
