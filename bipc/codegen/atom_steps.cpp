// Atom steps as straight C++: the transitions of each atom type examined in the order the
// engines' Runtime examines them, with the same outcomes (offers, conflicts, unsafe nets).
#include "bipc/codegen/atom_steps.h"

#include <cstddef>
#include <sstream>
#include <string>

#include "bipc/ir/clock_guard.h"

namespace smcbip::bipc::codegen {

namespace {

/// `m[a] && m[b]...` for the transition's `from` places (`true` when it has none).
std::string marked(const ir::Transition& t) {
  if (t.from.empty()) return "true";
  std::string text;
  for (ir::Index p : t.from) text += (text.empty() ? "m[" : " && m[") + std::to_string(p) + "]";
  return text;
}

std::string code_call(const ir::Code& code) { return "code_" + std::to_string(code.id) + "(c, f)"; }

/// The dates at which the guard of transition `t` of type `type_index` holds, as ModelCode's
/// holds_when answers for the generated code: guards that read no clock hold at all dates or
/// none; clock bounds by literals are narrowed in straight C++; other guards go to the time-set
/// evaluator.
std::string guard_window(const ir::AtomType& type, ir::Index type_index, ir::Index t) {
  const ir::Code& guard = type.transitions[t].guard;
  if (guard.empty()) return "se::Interval::all()";
  if (type.clocks.empty() || !ir::reads_clock(guard)) {
    return code_call(guard) + ".b ? se::Interval::all() : se::Interval::none()";
  }
  const std::string interpreted = "c.timed.holds_when(c.system.atom_types[" +
                                  std::to_string(type_index) + "].transitions[" +
                                  std::to_string(t) + "].guard, f)";
  const auto comparisons = ir::clock_comparisons(guard);
  if (!comparisons) return interpreted;
  // Clock bounds by literals: their dates in integers, unless out of the exact range (then the
  // time-set evaluator's floating point, as the engines' ClockBounds does).
  std::string exact;
  for (const ir::ClockComparison& comparison : *comparisons) {
    if (!comparison.small_literal) return interpreted;
    const std::string clock = std::to_string(comparison.clock);
    exact += std::string(exact.empty() ? "" : " &&\n            ") +
             "se::narrow_to_clock_bound(static_cast<ir::Op>(" +
             std::to_string(static_cast<unsigned>(comparison.clock_op)) + "), INT64_C(" +
             std::to_string(*comparison.small_literal) + "), f.clocks[" + clock +
             "], f.clock_units[" + clock + "], f.now, dates)";
  }
  return "[&] {\n          se::Interval dates = se::Interval::all();\n          if (" + exact +
         ") {\n            return dates;\n          }\n          return " + interpreted +
         ";\n        }()";
}

void offer(std::ostream& out, const ir::AtomType& type, ir::Index type_index, ir::Index t,
           const std::string& indent) {
  const ir::Transition& tr = type.transitions[t];
  out << indent << "{  // " << type.ports[tr.port].name << "\n"
      << indent << "  const se::Interval w = " << guard_window(type, type_index, t) << ";\n"
      << indent << "  if (!w.empty()) {\n"
      << indent << "    if (v[" << tr.port << "]) return " << tr.port << ";\n"
      << indent << "    v[" << tr.port << "] = se::AtomPortValue{" << t << ", {w, "
      << "static_cast<ir::Urgency>(" << static_cast<unsigned>(tr.urgency) << ")}};\n"
      << indent << "  }\n"
      << indent << "}\n";
}

/// The attributes of an atom type's step function: inlined into the compiled step path's
/// calls when the type is small, which saves a call and a frame per fired atom; a large type's
/// stay calls, so that each call site does not copy its switch.
std::string step_function_attributes(const ir::AtomType& type) {
  constexpr std::size_t kInlinedTransitions = 16;
  if (type.transitions.size() > kInlinedTransitions) return "[[maybe_unused]] ";
  return "[[maybe_unused]] [[gnu::always_inline]] inline ";
}

void offers_function(std::ostream& out, const ir::AtomType& type, ir::Index type_index) {
  out << step_function_attributes(type) << "ir::Index offers_" << type_index
      << "(void* context, [[maybe_unused]] const std::uint8_t* m,\n"
      << "    [[maybe_unused]] const se::Frame& f, [[maybe_unused]] "
         "std::optional<se::AtomPortValue>* "
         "v) {\n"
      << "  [[maybe_unused]] Context& c = *static_cast<Context*>(context);\n";
  if (ir::is_state_machine(type)) {
    // Only the transitions from the one marked place (the last one if none is).
    out << "  std::size_t marked = 0;\n"
        << "  while (marked + 1 < " << type.places.size() << " && !m[marked]) ++marked;\n"
        << "  if (!m[marked]) return ir::kNone;\n"
        << "  switch (marked) {\n";
    for (ir::Index p = 0; p < type.places.size(); ++p) {
      out << "    case " << p << ":  // " << type.places[p] << "\n";
      for (ir::Index t = 0; t < type.transitions.size(); ++t) {
        const ir::Transition& tr = type.transitions[t];
        if (tr.port != ir::kNone && tr.from.front() == p) offer(out, type, type_index, t, "      ");
      }
      out << "      break;\n";
    }
    out << "    default:\n      break;\n  }\n";
  } else {
    for (ir::Index t = 0; t < type.transitions.size(); ++t) {
      const ir::Transition& tr = type.transitions[t];
      if (tr.port == ir::kNone) continue;
      out << "  if (" << marked(tr) << ")\n";
      offer(out, type, type_index, t, "  ");
    }
  }
  out << "  return ir::kNone;\n}\n\n";
}

void internal_function(std::ostream& out, const ir::AtomType& type, ir::Index type_index) {
  out << step_function_attributes(type) << "ir::Index internal_" << type_index
      << "(void* context, [[maybe_unused]] const std::uint8_t* m,\n"
      << "    [[maybe_unused]] const se::Frame& f) {\n"
      << "  [[maybe_unused]] Context& c = *static_cast<Context*>(context);\n"
      << "  ir::Index enabled = ir::kNone;\n";
  for (ir::Index t = 0; t < type.transitions.size(); ++t) {
    const ir::Transition& tr = type.transitions[t];
    if (tr.port != ir::kNone) continue;
    out << "  if (" << marked(tr);
    if (!tr.guard.empty()) out << " && " << code_call(tr.guard) << ".b";
    out << ") {\n"
        << "    if (enabled != ir::kNone) return se::ModelCode::kSeveralTransitions;\n"
        << "    enabled = " << t << ";\n  }\n";
  }
  out << "  return enabled;\n}\n\n";
}

void fire_function(std::ostream& out, const ir::AtomType& type, ir::Index type_index) {
  out << step_function_attributes(type) << "bool fire_" << type_index
      << "(void* context, ir::Index t, [[maybe_unused]] std::uint8_t* m,\n"
      << "    [[maybe_unused]] const se::Frame& f) {\n"
      << "  [[maybe_unused]] Context& c = *static_cast<Context*>(context);\n"
      << "  switch (t) {\n";
  for (ir::Index t = 0; t < type.transitions.size(); ++t) {
    const ir::Transition& tr = type.transitions[t];
    out << "    case " << t << ":\n";
    for (ir::Index p : tr.from) out << "      m[" << p << "] = 0;\n";
    for (ir::Index p : tr.to) {
      out << "      if (m[" << p << "]) return false;\n      m[" << p << "] = 1;\n";
    }
    if (!tr.action.empty()) out << "      " << code_call(tr.action) << ";\n";
    out << "      return true;\n";
  }
  out << "    default:\n      break;\n  }\n"
      << "  throw se::CodeFault{\"transition \" + std::to_string(t) + \" is not one of atom type "
      << type_index << "\"};\n}\n\n";
}

/// CompiledAtomSteps::fire_and_offer: the type's own fire, internal and offers functions
/// called straight (inlined when the type is small), the internal loop only where the type has
/// internal transitions and the offers reset port by port as the engines reset them.
void fire_and_offer_function(std::ostream& out, const ir::AtomType& type, ir::Index type_index) {
  const std::string n = std::to_string(type_index);
  out << "bool fire_and_offer_" << n
      << "(void* context, ir::Index t, std::uint8_t* m, const se::Frame& f,\n"
      << "    std::optional<se::AtomPortValue>* v) {\n"
      << "  if (!fire_" << n << "(context, t, m, f)) return false;\n";
  bool internal = false;
  for (const ir::Transition& tr : type.transitions) internal = internal || tr.port == ir::kNone;
  if (internal) {
    out << "  for (;;) {\n"
        << "    const ir::Index next = internal_" << n << "(context, m, f);\n"
        << "    if (next == ir::kNone) break;\n"
        << "    if (next == se::ModelCode::kSeveralTransitions || !fire_" << n
        << "(context, next, m, f)) {\n"
        << "      return false;\n    }\n  }\n";
  }
  if (!type.ports.empty()) {
    out << "  for (std::size_t p = 0; p < " << type.ports.size() << "; ++p) v[p].reset();\n";
  }
  out << "  return offers_" << n << "(context, m, f, v) == ir::kNone;\n}\n\n";
}

}  // namespace

AtomStepFunctions atom_step_functions(const ir::System& system) {
  AtomStepFunctions functions;
  std::ostringstream out;
  for (ir::Index k = 0; k < system.atom_types.size(); ++k) {
    const ir::AtomType& type = system.atom_types[k];
    out << "// Atom type " << type.name << ".\n\n";
    offers_function(out, type, k);
    internal_function(out, type, k);
    fire_function(out, type, k);
    fire_and_offer_function(out, type, k);
    const std::string label = "      case " + std::to_string(k) + ": return ";
    const std::string n = std::to_string(k);
    functions.offers_cases += label + "offers_" + n + "(&c_, m, f, v);\n";
    functions.internal_cases += label + "internal_" + n + "(&c_, m, f);\n";
    functions.fire_cases += label + "fire_" + n + "(&c_, t, m, f);\n";
    functions.table_entries +=
        "    {offers_" + n + ", internal_" + n + ", fire_" + n + ", fire_and_offer_" + n + "},\n";
  }
  functions.definitions = out.str();
  return functions;
}

}  // namespace smcbip::bipc::codegen
