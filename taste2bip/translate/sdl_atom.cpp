// The SDL process translation's entry point: the declarations of the atom (interface data,
// timers, variables, inlined procedures' data) and the assembly of its text.
#include "taste2bip/translate/sdl_atom.h"

#include <algorithm>
#include <cctype>

#include "taste2bip/names.h"
#include "taste2bip/translate/detail/sdl_translator.h"

namespace smcbip::taste2bip {

namespace detail {

std::string signal_key(const std::string& name) { return bip_identifier(folded(name)); }

std::string folded(const std::string& name) { return folded_name(name); }

void Outcome::merge(Outcome other) {
  for (Step& s : other.falls) falls.push_back(std::move(s));
  for (Step& s : other.returns) returns.push_back(std::move(s));
}

Translator::Translator(const FunctionSignature& function, const sdl::Process& process,
                       const std::vector<const sdl::Procedure*>& procedures,
                       const asn1::DataView& data, bipc::Diagnostics& diags)
    : function_(function), process_(process), data_(data), diags_(diags) {
  for (const sdl::Procedure* p : procedures) procedures_[folded(p->name)].push_back(p);
  for (const sdl::Procedure& p : process.body.procedures) {
    procedures_[folded(p.name)].push_back(&p);
  }
  errors_before_ = diags.error_count();
}

void Translator::need_function(const std::string& prototype) {
  const std::string line = "extern function " + prototype;
  if (std::find(extern_functions_.begin(), extern_functions_.end(), line) ==
      extern_functions_.end()) {
    extern_functions_.push_back(line);
  }
}

void Translator::error(const bipc::Location& at, const std::string& message) {
  if (!quiet_) diags_.error(at, message);
}

std::string Translator::fresh(const std::string& base) {
  std::string name = base;
  for (int k = 1; used_.count(name) > 0; ++k) name = base + "_" + std::to_string(k);
  used_.insert(name);
  return name;
}

void Translator::declare_timers() {
  std::vector<std::string> names;
  for (const sdl::Timer& t : process_.body.timers) names.push_back(t.name);
  for (const std::string& t : function_.context_timers) names.push_back(t);
  for (const std::string& t : names) {
    if (timers_.count(signal_key(t)) > 0) continue;
    const std::string base = bip_identifier(t);
    timers_[signal_key(t)] = base;
    for (const char* suffix : {"_clock", "_armed", "_value", "_expired"}) reserve(base + suffix);
    data_text_ += "    clock " + base + "_clock unit millisecond\n    data bool " + base +
                  "_armed = false\n    data int " + base + "_value = 0\n";
    ports_text_ += "    port Port " + base + "_expired()\n";
  }
}

void Translator::declare_variables() {
  scopes_.emplace_back();
  for (const sdl::Variable& v : process_.body.variables) {
    if (scopes_.back().count(folded(v.name)) > 0) {
      error(v.at, "variable '" + v.name + "' is declared twice (SDL names ignore case)");
      continue;
    }
    std::optional<Ref> ref = declare_sdl_variable(v, "");
    if (!ref) continue;
    scopes_.back()[folded(v.name)] = Binding{*ref, 0};
    if (v.initial) assign(*ref, *v.initial, initial_statements_);
  }
}

void Translator::declare_context() {
  for (const ContextValue& c : function_.context) {
    Ref ref{fresh("ctxt_" + c.name), c.leaves, nullptr};
    if (const auto id = find_type_spelled(data_, c.asn1_type)) {
      ref.type = definition(data_, data_.type(*id)->type);
    }
    declare_variable(ref.data, ref.leaves);
    context_[folded(c.name)] = ref;
    const std::string v = folded(c.value);
    const bool number = !v.empty() && v.find_first_not_of("+-.0123456789e") == std::string::npos;
    if (ref.leaves.size() == 1 && ref.leaves[0].suffix.empty() &&
        (number || v == "true" || v == "false")) {
      initial_statements_.push_back(ref.data + " = " + v + ";");
    } else if (!c.value.empty()) {
      notes_.push_back("context parameter " + c.name + " = " + c.value +
                       ": not set (only single numbers and booleans are)");
    }
  }
}

void Translator::declare_procedure(const sdl::Procedure& p, const std::string& level_prefix) {
  if (p.is_external || p.is_referenced) return;
  const std::string prefix = level_prefix + bip_identifier(p.name) + "_";
  auto& scope = procedure_scopes_[&p];
  for (const sdl::FormalParameter& f : p.parameters) {
    std::optional<Ref> ref = declare_sdl_variable(sdl::Variable{f.name, f.type, {}, f.at}, prefix);
    if (!ref) continue;
    scope[folded(f.name)] = Binding{*ref, 0};
    procedure_parameters_[&p].push_back(*ref);
  }
  for (const sdl::Variable& v : p.body.variables) {
    std::optional<Ref> ref = declare_sdl_variable(v, prefix);
    if (ref) scope[folded(v.name)] = Binding{*ref, 0};
  }
  if (!p.return_type.empty()) {
    const std::string name = p.return_name.empty() ? "result" : p.return_name;
    std::optional<Ref> ref =
        declare_sdl_variable(sdl::Variable{name, p.return_type, {}, p.at}, prefix);
    if (ref && !p.return_name.empty()) scope[folded(p.return_name)] = Binding{*ref, 0};
    if (ref) procedure_results_[&p] = *ref;
  }
  if (!p.body.procedures.empty() || !p.body.composite_states.empty() || !p.body.states.empty() ||
      !p.body.timers.empty()) {
    error(p.at, "procedure '" + p.name +
                    "' has states, timers or nested procedures, which are not translated");
  }
}

std::optional<AtomType> Translator::run() {
  for (const auto* list : {&function_.provided, &function_.required}) {
    for (const SignalInterface& i : *list) {
      for (bool out : {false, true}) {
        for (const std::string& n : i.data_names(out)) reserve(n);
      }
      for (const char* port : {"_in", "_return", "_out", "_result"}) reserve(i.name + port);
    }
  }
  if (faults_only_) {
    for (const SignalInterface& p : function_.provided) {
      if (!is_fault_interface(p)) continue;
      reserve(p.name + "_fault");
      ports_text_ += "    @fault\n    port Port " + p.name + "_fault()\n";
    }
  }
  declare_timers();
  declare_context();
  declare_variables();
  for (const auto& [name, list] : procedures_) {
    for (const sdl::Procedure* p : list) declare_procedure(*p);
  }
  build_level(process_.body, "", nullptr, nullptr);
  const bool aggregation = std::any_of(composite_levels_.begin(), composite_levels_.end(),
                                       [](const auto& c) { return c.first->is_aggregation; });
  if (!aggregation) {
    ready_place_ = fresh("ready");  // after the states, which keep their SDL names
  } else {
    notes_.push_back(
        "state aggregation: while a transition runs, the atom is in an intermediate "
        "place, which properties see");
  }
  label_tables_.emplace_back();
  for (const auto& level : levels_) collect_body_labels(*level->body, label_tables_.back());
  translate_start();
  for (const StableState& state : std::vector<StableState>(stable_)) translate_state(state);
  translate_entries();
  if (diags_.error_count() > errors_before_) return std::nullopt;
  AtomType atom;
  atom.name = faults_only_ ? function_.name + "_faulty" : function_.name;
  atom.text = text();
  atom.extern_types = extern_types_;
  atom.extern_functions = extern_functions_;
  atom.notes = notes_;
  return atom;
}

std::string Translator::text() const {
  std::string out =
      "  atom type " + (faults_only_ ? function_.name + "_faulty" : function_.name) + "()\n";
  out += interface_declarations(function_);
  out += data_text_ + ports_text_;
  for (const std::string& port : port_order_) out += "    port Port " + port + "()\n";
  std::string places;
  for (const std::string& p : places_) places += (places.empty() ? "" : ", ") + p;
  if (!ready_place_.empty()) places += (places.empty() ? "" : ", ") + ready_place_;
  if (!places.empty()) out += "    place " + places + "\n";
  out += transitions_text_;
  return out + "  end\n";
}

}  // namespace detail

std::optional<AtomType> sdl_atom(const FunctionSignature& function, const sdl::Process& process,
                                 const std::vector<const sdl::Procedure*>& procedures,
                                 const asn1::DataView& data, bipc::Diagnostics& diags) {
  detail::Translator translator(function, process, procedures, data, diags);
  return translator.run();
}

std::optional<AtomType> sdl_fault_atom(const FunctionSignature& function,
                                       const sdl::Process& process,
                                       const std::vector<const sdl::Procedure*>& procedures,
                                       const asn1::DataView& data, bipc::Diagnostics& diags) {
  detail::Translator translator(function, process, procedures, data, diags);
  translator.faults_only_ = true;
  return translator.run();
}

bool is_fault_interface(const SignalInterface& provided) {
  return detail::folded(provided.name).rfind("fault", 0) == 0;
}

}  // namespace smcbip::taste2bip
