// A function of the (flattened) interface view as the BIP it becomes sees it: its interfaces
// with their parameters spread over BIP data, the kinds of the interfaces its required ones
// reach, its timers and context parameters. The atom of a function (translated from SDL, or
// abstract) and the compound that connects the atoms agree on the ports through this contract:
//
//   provided interface p:  export port <PT(in leaves)>  p_in(p_<param>_<leaf>...)   the call
//                          export port <PT(out leaves)> p_return(p_<param>_<leaf>...) its end
//   required interface r:  export port <PT(in leaves)>  r_out(r_<param>_<leaf>...)   a call
//                          export port <PT(out leaves)> r_result(r_<param>_<leaf>...) its end,
//                          for a synchronous one (protected or unprotected) only
//
// (the data's names start with SignalInterface::data_prefix, which is `r_ri` for a required
// interface named like a provided one)
//
// where PT is port_type_name of the leaves' types. The atom sets the out data before the port
// fires; the connectors copy the data of the sending port into the receiving one.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/interface_view/interface_view.h"
#include "taste2bip/translate/bip_types.h"

namespace smcbip::taste2bip {

/// A parameter of an interface, spread over BIP data.
struct SignalParameter {
  std::string name;       // as a BIP identifier
  std::string asn1_type;  // as the view spells it
  bool out = false;
  std::vector<Leaf> leaves;
  bipc::Location at;
};

struct SignalInterface {
  std::string name;  // as a BIP identifier
  /// What the names of its data start with: `name`, or for a required interface named like one
  /// of the function's provided ones, `name` + `_ri` (TASTE allows both to share a name), and
  /// `_data` appended when a data name would be a port's (a parameter named `result`). Empty
  /// means `name`.
  std::string data_prefix;
  /// The kind of a provided interface; for a required one, the kind of the provided interface
  /// it is connected to (Any when it is connected to none).
  InterfaceKind kind = InterfaceKind::Any;
  std::vector<SignalParameter> parameters;
  const Interface* source = nullptr;  // in the flattened view
  bipc::Location at;

  /// The BIP data of parameter `p` (its leaves' names start with it): `<data_prefix>_<p>`.
  std::string data_of(const SignalParameter& p) const {
    return (data_prefix.empty() ? name : data_prefix) + "_" + p.name;
  }
  bool synchronous() const {
    return kind == InterfaceKind::Protected || kind == InterfaceKind::Unprotected;
  }
  /// The BIP data names (`<data_prefix>_<param>_<leaf>`) and types of the in (or out) parameters.
  std::vector<std::string> data_names(bool out) const;
  std::vector<std::string> data_types(bool out) const;
};

/// A context parameter: a value of an ASN.1 type (`value` as written in ASN.1 value notation) or
/// a timer.
struct ContextValue {
  std::string name;  // as a BIP identifier
  std::string asn1_type;
  std::string value;
  std::vector<Leaf> leaves;
  bipc::Location at;
};

struct FunctionSignature {
  std::string name;  // as a BIP identifier: the atom type's and the instance's name
  std::string language;
  std::vector<SignalInterface> provided, required;
  std::vector<ContextValue> context;        // context parameters that are values
  std::vector<std::string> context_timers;  // context parameters of type Timer
  const Function* source = nullptr;         // in the flattened view
};

/// The signature of `view.functions[index]` (`view` flattened). Parameter types missing from
/// `data` are errors at the parameter.
FunctionSignature function_signature(const InterfaceView& view, std::size_t index,
                                     const asn1::DataView& data, bipc::Diagnostics& diags);

/// Gives the interfaces of `f` data names of their own: a required interface named like a
/// provided one takes the prefix `<name>_ri`, an interface whose data would be named like a port
/// `<prefix>_data`. function_signature and sdl_system_signature apply it.
void separate_data_names(FunctionSignature& f);

/// The data and port declarations of the contract above, as atom type body lines.
std::string interface_declarations(const FunctionSignature& function);

/// The port types the contract needs for `function` (port_type_name -> its types), to declare
/// once per package; appended to `into` when missing.
void collect_port_types(const FunctionSignature& function,
                        std::vector<std::pair<std::string, std::vector<std::string>>>& into);

}  // namespace smcbip::taste2bip
