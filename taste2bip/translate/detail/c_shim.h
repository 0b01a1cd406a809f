// The extern functions between a function's atom and its C body (c_body.h): their names, the
// BIP prototypes the package declares and the C++ that defines them in the shim.
//
// For function F: `F_bip_startup()` (at each run's start: context parameters, then
// `<f>_startup`), `int F_bip_call_<p>(in leaves...)` (a call of provided p: 0 when the body
// returned, k when it is paused in a call of the k-th required interface), `int
// F_bip_resume()` (after that call), `F_bip_get_<data>()` (an out leaf of p once returned, or
// an in leaf of the paused call) and `F_bip_set_<data>(v)` (an out leaf of a synchronous call,
// before resuming). `<data>` is the leaf's BIP data name (signature.h). Timers: below.
#pragma once

#include <string>
#include <vector>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/translate/signature.h"

namespace smcbip::taste2bip::detail {

struct ShimCall {
  std::string name;
  std::string result;               // BIP type; empty: none
  std::vector<std::string> params;  // BIP types
  std::string definition;           // C++
};

std::string shim_startup(const FunctionSignature& f);
std::string shim_call(const FunctionSignature& f, const SignalInterface& provided);
std::string shim_resume(const FunctionSignature& f);
/// `int F_bip_expire_<t>()`: timer t expired, its `<f>_PI_<t>` runs (as shim_call's call).
std::string shim_call_timer(const FunctionSignature& f, const std::string& timer);
/// `int F_bip_timer_value()`: the value the paused body set a timer to (ms).
std::string shim_timer_value(const FunctionSignature& f);
/// The status of a body paused in setting (or resetting) its k-th timer: after the required
/// interfaces' 1..n, `n + 2k + 1` (`n + 2k + 2`).
int timer_status(const FunctionSignature& f, std::size_t k, bool set);
std::string shim_get(const FunctionSignature& f, const std::string& data);
std::string shim_set(const FunctionSignature& f, const std::string& data);

/// `extern function int F_bip_call_p(int, bool)`.
std::string bip_declaration(const ShimCall& call);

/// The C names of TASTE's glue for `f`: `<function, lower case>` and an interface's name.
std::string c_function_name(const FunctionSignature& f);
std::string c_interface_name(const SignalInterface& i);

/// The field of `<f>_ctxt` holding context parameter `c`: its name in lower case, as TASTE's
/// glue writes it.
std::string c_context_field(const ContextValue& c);

/// The C type of a parameter or context value spelled `asn1_type` in the view.
std::string c_parameter_type(const asn1::DataView& data, const std::string& asn1_type);

/// Everything the shim defines for `f`: its state (buffers, the paused call's arguments, the
/// activation), the required interfaces' C entry points, and `calls`.
struct FunctionShim {
  std::string state;             // in the shim's anonymous namespace
  std::string required_entries;  // `extern "C"` <f>_RI_<r> and timer calls the body makes
  std::string context;           // the definition of `<f>_ctxt`, when f has context parameters
  std::vector<ShimCall> calls;
};

/// The shim of `f`. Its parameters' leaves are scalar and reachable (c_body_atom checked).
FunctionShim function_shim(const FunctionSignature& f, const asn1::DataView& data);

}  // namespace smcbip::taste2bip::detail
