// An SDL process (OpenGEODE's SDL-PR) as a BIP atom type with the ports of signature.h. SDL
// states are places; a transition runs to completion through intermediate places left by
// internal or eager steps only, so between two interface calls the atom rests in an SDL state.
//
// What the atom contains, besides the contract's data and ports:
//  - one data per leaf of each variable (bip_types.h), procedure locals and parameters
//    prefixed `<procedure>_`, a composite state's variables `<Composite>_`;
//  - places: each state under its own name (substates of composite states as
//    `<Composite>_<Sub>`), intermediate places `<State>__<n>` (`START__<n>` in the start
//    transition), never a data's name;
//  - every step eager: a provided interface's call `p_in` from a state, the chain's internal
//    steps (ports `silent`, `silent_1`... of type `Port`, one per answer of a decision so that
//    answers never share a port), outputs `r_out` (and `r_result` for a synchronous required
//    interface), then `p_return` into the next state. `p_return` and `r_result` are lazy: the
//    interface's wrapper, which joins them, gives them their date. A call the state does not
//    handle is consumed (`p_in` then `p_return`); a saved one waits in the caller's FIFO;
//  - in a process without nested states, a place `ready` whose token a transition takes while
//    it runs, the state's place staying marked (`from S, ready to S, S__1` ... `from S, S__2 to
//    T, ready`): properties see the SDL state, never a transition's intermediate place;
//  - per timer t: `clock t_clock`, `t_armed`, `t_value` and the internal port `t_expired`, which
//    fires in a state once armed and `t_clock >= t_value`;
//  - a composite state is entered at a place named after it (`<Composite>_via_<entry>` for an
//    entry point) from which its start runs, after the return of the call that entered it; a
//    state aggregation marks one place per region, each region with its own internal ports
//    and a `<Aggregation>_busy` flag that lets one region's transition run at a time.
// Procedures are inlined at each call; `for` loops over constant ranges are unrolled, others
// become loops of places. The package must declare the port type `Port` (no parameters) for
// the internal ports, and the atom's `extern_functions`.
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

/// The faulty package's atom `<F>_faulty` of `function` (FDIR): the interface, data and states of
/// sdl_atom's and its start transition, and as its only behaviour the inputs of the provided
/// interfaces named `fault...` (case ignored) as fault transitions: on the internal port
/// `<p>_fault`, marked `@fault` and lazy (a fault comes when it comes), with no caller and no
/// return. The user adds the other faulty behaviour. Errors as sdl_atom.
std::optional<AtomType> sdl_fault_atom(const FunctionSignature& function,
                                       const sdl::Process& process,
                                       const std::vector<const sdl::Procedure*>& procedures,
                                       const asn1::DataView& data, bipc::Diagnostics& diags);

/// Whether a provided interface is a fault signal of the FDIR workflow: named `fault...`.
bool is_fault_interface(const SignalInterface& provided);

/// The signature of a process declared inside an SDL system (the OpenGEODE test designs have
/// no interface view): signals from the environment to it are sporadic provided interfaces,
/// signals from it to the environment sporadic required ones, with the parameter types of
/// their declarations.
std::optional<FunctionSignature> sdl_system_signature(const sdl::System& system,
                                                      const std::string& process,
                                                      const asn1::DataView& data,
                                                      bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip
