#include "taste2bip/translate/abstract_atom.h"

#include <string>

namespace smcbip::taste2bip {

namespace {

/// `<interface>__<step>`: the places of one activation (double '_' keeps them apart from data).
std::string step_place(const SignalInterface& provided, std::size_t step) {
  return provided.name + "__" + std::to_string(step);
}

/// The transitions of one activation of `provided`: the call, each required interface called
/// or skipped, the return (lazy: the wrapper's `done` decides when).
std::string activation(const FunctionSignature& function, const SignalInterface& provided) {
  std::string text =
      "    on " + provided.name + "_in from idle to " + step_place(provided, 0) + " eager\n";
  for (std::size_t k = 0; k < function.required.size(); ++k) {
    const SignalInterface& r = function.required[k];
    const std::string from = step_place(provided, k), to = step_place(provided, k + 1);
    if (r.synchronous()) {
      const std::string waiting = from + "_" + r.name;
      text += "    on " + r.name + "_out from " + from + " to " + waiting + " eager\n";
      text += "    on " + r.name + "_result from " + waiting + " to " + to + "\n";
    } else {
      text += "    on " + r.name + "_out from " + from + " to " + to + " eager\n";
    }
    text += "    on skip from " + from + " to " + to + " eager\n";
  }
  text += "    on " + provided.name + "_return from " +
          step_place(provided, function.required.size()) + " to idle\n";
  return text;
}

std::string places(const FunctionSignature& function) {
  std::string text = "    place idle";
  for (const SignalInterface& p : function.provided) {
    for (std::size_t k = 0; k <= function.required.size(); ++k) {
      text += ", " + step_place(p, k);
      if (k < function.required.size() && function.required[k].synchronous()) {
        text += ", " + step_place(p, k) + "_" + function.required[k].name;
      }
    }
  }
  return text + "\n";
}

}  // namespace

AtomType abstract_atom(const FunctionSignature& function) {
  AtomType atom;
  atom.name = function.name;
  std::string& text = atom.text;
  text += "  // " + function.name + " (" +
          (function.language.empty() ? "no language" : function.language) +
          "): no behaviour in the design; each activation may call each required interface\n"
          "  // once, in order, or skip it.\n";
  text += "  atom type " + function.name + "()\n";
  text += interface_declarations(function);
  text += "    port Port skip()\n";
  text += places(function);
  text += "    initial to idle\n";
  for (const SignalInterface& p : function.provided) text += activation(function, p);
  text += "  end\n";
  atom.notes.push_back(function.name +
                       ": abstract atom (no behaviour in the design): each call of a "
                       "provided interface may call each required interface once, in order, "
                       "with the data's current values");
  return atom;
}

}  // namespace smcbip::taste2bip
