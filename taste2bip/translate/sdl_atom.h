// An SDL process (OpenGEODE's SDL-PR) as a BIP atom type with the ports of signature.h. SDL
// states are places; a transition runs to completion through intermediate places left by
// internal or eager steps only, so between two interface calls the atom rests in an SDL state.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/sdl/sdl_ast.h"
#include "taste2bip/translate/signature.h"

namespace smcbip::taste2bip {

struct AtomType {
  std::string name;  // the atom type's name
  std::string text;  // `atom type NAME() ... end`, indented as a package member
  /// Package-level declarations the atom needs (extern data types), each once.
  std::vector<std::string> extern_types;
  /// Package-level prototypes of the builtin functions the atom calls (`printf` for writeln,
  /// `abs`, `max`), each once: `extern function printf(string, int)`.
  std::vector<std::string> extern_functions;
  /// What the translation assumed or left out, one line each, for the report.
  std::vector<std::string> notes;
};

/// The atom of `function` behaving as `process`. `procedures` are the procedures declared
/// outside the process (in its file or system), visible to it. What the translation does not
/// support is a located error in `diags` (nullopt then), never a silent omission.
std::optional<AtomType> sdl_atom(const FunctionSignature& function, const sdl::Process& process,
                                 const std::vector<const sdl::Procedure*>& procedures,
                                 const asn1::DataView& data, bipc::Diagnostics& diags);

/// The signature of a process declared inside an SDL system (the OpenGEODE test designs have
/// no interface view): signals from the environment to it are sporadic provided interfaces,
/// signals from it to the environment sporadic required ones, with the parameter types of
/// their declarations.
std::optional<FunctionSignature> sdl_system_signature(const sdl::System& system,
                                                      const std::string& process,
                                                      const asn1::DataView& data,
                                                      bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip
