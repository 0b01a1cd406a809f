#include "taste2bip/translate/c_body.h"
#include "taste2bip/translate/c_types.h"
#include "taste2bip/translate/detail/c_shim.h"

namespace smcbip::taste2bip {

namespace {

using detail::shim_call;
using detail::shim_get;
using detail::shim_resume;
using detail::shim_set;

const std::string kStatus = "body__status";
const std::string kStep = "body__step";

/// Errors for what the shim cannot pass between the model and the body.
bool passable(const FunctionSignature& f, const asn1::DataView& data, bipc::Diagnostics& diags) {
  bool ok = true;
  for (const auto* list : {&f.provided, &f.required}) {
    for (const SignalInterface& i : *list) {
      for (const SignalParameter& p : i.parameters) {
        const auto id = find_type_spelled(data, p.asn1_type);
        const asn1::TypeAssignment* a = id ? data.type(*id) : nullptr;
        for (const Leaf& leaf : p.leaves) {
          const bool scalar = leaf.type == "int" || leaf.type == "bool" || leaf.type == "float" ||
                              leaf.type == "string";
          if (scalar && a != nullptr && a->parameters.empty() && c_access(data, a->type, leaf)) {
            continue;
          }
          diags.error(p.at, "parameter " + p.name + " of " + i.source->name + " (" + p.asn1_type +
                                "): a C/C++ body's parameters pass through the model as "
                                "scalars, and this one has a part without a scalar form (" +
                                leaf.type + ")");
          ok = false;
          break;
        }
      }
    }
  }
  return ok;
}

std::string place(const SignalInterface& p, const std::string& what) {
  return p.name + "__" + what;
}

/// The places of an activation of `name` (a provided interface or a timer's expiry).
std::string activation_places(const FunctionSignature& f, const std::string& name, bool done) {
  std::string text = ", " + name + "__run" + (done ? ", " + name + "__done" : "");
  for (const SignalInterface& r : f.required) {
    text += ", " + name + "__" + r.name;
    if (r.synchronous()) text += ", " + name + "__" + r.name + "__wait";
  }
  return text;
}

std::string places(const FunctionSignature& f) {
  std::string text = "    place idle";
  for (const SignalInterface& p : f.provided) text += activation_places(f, p.name, true);
  for (const std::string& t : f.context_timers) text += activation_places(f, t, false);
  return text + "\n";
}

/// A timer's data: its clock, whether it is set, and the date it expires at (ms).
std::string timer_data(const std::string& t) {
  return "    clock " + t + "__clock unit millisecond\n    data bool " + t +
         "__armed = false\n    data int " + t + "__value = 0\n";
}

/// `x = F_bip_get_x(); ...` for the data of `i`'s in (or out) parameters.
std::string reads(const FunctionSignature& f, const SignalInterface& i, bool out) {
  std::string text;
  for (const std::string& d : i.data_names(out)) text += " " + d + " = " + shim_get(f, d) + "();";
  return text;
}

std::string action(const std::string& statements) {
  return statements.empty() ? "" : " do {" + statements + " }";
}

/// The required interface `r` (number k) called from an activation of `p`: its data read from
/// the paused body, the call, and the body resumed (after the result, for a synchronous one).
std::string call_steps(const FunctionSignature& f, const std::string& activation,
                       const SignalInterface& r, std::size_t k) {
  const std::string run = activation + "__run", call = activation + "__" + r.name;
  const std::string resume = " " + kStatus + " = " + shim_resume(f) + "();";
  std::string text = "    on " + kStep + " from " + run + " to " + call + " provided (" + kStatus +
                     " == " + std::to_string(k) + ") eager" + action(reads(f, r, false)) + "\n";
  if (!r.synchronous()) {
    return text + "    on " + r.name + "_out from " + call + " to " + run + " eager" +
           action(resume) + "\n";
  }
  const std::string wait = call + "__wait";
  std::string results;
  for (const std::string& d : r.data_names(true)) results += " " + shim_set(f, d) + "(" + d + ");";
  text += "    on " + r.name + "_out from " + call + " to " + wait + " eager\n";
  return text + "    on " + r.name + "_result from " + wait + " to " + run +
         action(results + resume) + "\n";
}

/// While an activation runs, the body's calls of required interfaces and its timer requests.
std::string body_steps(const FunctionSignature& f, const std::string& activation) {
  std::string text;
  for (std::size_t k = 0; k < f.required.size(); ++k) {
    text += call_steps(f, activation, f.required[k], k + 1);
  }
  const std::string run = activation + "__run";
  const std::string resume = " " + kStatus + " = " + shim_resume(f) + "(); }\n";
  for (std::size_t k = 0; k < f.context_timers.size(); ++k) {
    const std::string& t = f.context_timers[k];
    const std::string loop =
        "    on " + kStep + " from " + run + " to " + run + " provided (" + kStatus + " == ";
    text += loop + std::to_string(detail::timer_status(f, k, true)) + ") eager do { " + t +
            "__value = " + detail::shim_timer_value(f) + "(); " + t + "__clock = 0; " + t +
            "__armed = true;" + resume;
    text += loop + std::to_string(detail::timer_status(f, k, false)) + ") eager do { " + t +
            "__armed = false;" + resume;
  }
  return text;
}

std::string activation(const FunctionSignature& f, const SignalInterface& p) {
  std::string arguments;
  for (const std::string& d : p.data_names(false)) arguments += (arguments.empty() ? "" : ", ") + d;
  const std::string run = place(p, "run"), done = place(p, "done");
  std::string text = "    on " + p.name + "_in from idle to " + run + " eager do { " + kStatus +
                     " = " + shim_call(f, p) + "(" + arguments + "); }\n";
  text += "    on " + kStep + " from " + run + " to " + done + " provided (" + kStatus +
          " == 0) eager" + action(reads(f, p, true)) + "\n";
  text += "    on " + p.name + "_return from " + done + " to idle\n";
  return text + body_steps(f, p.name);
}

/// A timer's expiry, when the function is idle: its `<f>_PI_<t>` runs to its end.
std::string timer_activation(const FunctionSignature& f, const std::string& t) {
  const std::string run = t + "__run";
  std::string text = "    on " + kStep + " from idle to " + run + " provided (" + t +
                     "__armed && " + t + "__clock >= " + t + "__value) eager do { " + t +
                     "__armed = false; " + kStatus + " = " + detail::shim_call_timer(f, t) +
                     "(); }\n";
  text += "    on " + kStep + " from " + run + " to idle provided (" + kStatus + " == 0) eager\n";
  return text + body_steps(f, t);
}

}  // namespace

std::optional<AtomType> c_body_atom(const FunctionSignature& function, const asn1::DataView& data,
                                    bipc::Diagnostics& diags) {
  if (!passable(function, data, diags)) return std::nullopt;
  AtomType atom;
  atom.name = function.name;
  for (const detail::ShimCall& call : detail::function_shim(function, data).calls) {
    atom.extern_functions.push_back(detail::bip_declaration(call));
  }
  std::string& text = atom.text;
  text += "  // " + function.name + " (" + function.language +
          "): its body, called through the extern functions of the bodies' shim; each call\n"
          "  // it makes of a required interface is a step of this atom.\n";
  text += "  atom type " + function.name + "()\n";
  text += interface_declarations(function);
  text += "    data int " + kStatus + " = 0\n";
  for (const std::string& t : function.context_timers) text += timer_data(t);
  text += "    port Port " + kStep + "()\n";
  text += places(function);
  text += "    initial to idle do { " + detail::shim_startup(function) + "(); }\n";
  for (const SignalInterface& p : function.provided) text += activation(function, p);
  for (const std::string& t : function.context_timers) text += timer_activation(function, t);
  text += "  end\n";
  atom.notes.push_back(function.name +
                       ": its C/C++ body, compiled in by bipc gen: the model runs compiled only "
                       "(the interpreter has no C); the body's own static data live as long "
                       "as the process, across the runs of one smcbip check");
  return atom;
}

}  // namespace smcbip::taste2bip
