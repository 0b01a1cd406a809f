// The SDL atom tests' harness: a tiny SDL process translated against a hand-made signature,
// put in a package with a driver that calls its provided interfaces on a script and a sink
// that takes its outputs, then run by the engines with each interaction's data recorded.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/engines.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "taste2bip/translate/sdl_atom.h"
#include "tests/engines/temp_model.h"

namespace smcbip::taste2bip::test {

struct ParamSpec {
  std::string name, type;
  bool out = false;
};

struct InterfaceSpec {
  std::string name;
  std::vector<ParamSpec> params;
  InterfaceKind kind = InterfaceKind::Sporadic;
};

struct ContextSpec {
  std::string name, type, value;
};

/// A function: its data view (ASN.1 module body), interfaces, context timers and values.
struct FunctionSpec {
  std::string asn1;
  std::vector<InterfaceSpec> provided, required;
  std::vector<std::string> timers;
  std::vector<ContextSpec> context = {};
};

/// The translation of one process: its atom, or the diagnostics (`line:col: error: ...`).
struct Translated {
  asn1::DataView view;
  FunctionSignature signature;
  std::optional<AtomType> atom;
  std::string errors;
};

inline SignalInterface interface_of(const InterfaceSpec& spec, const asn1::DataView& view,
                                    bipc::Diagnostics& diags) {
  SignalInterface i;
  i.name = spec.name;
  i.kind = spec.kind;
  for (const ParamSpec& p : spec.params) {
    auto leaves = leaves_of(view, p.type, {}, diags);
    i.parameters.push_back(
        SignalParameter{p.name, p.type, p.out, leaves.value_or(std::vector<Leaf>{}), {}});
  }
  return i;
}

/// Translates the process of `sdl` (a `process ... endprocess` text) as function `F`.
inline Translated translate_process(const FunctionSpec& spec, const std::string& sdl) {
  Translated t;
  bipc::Diagnostics diags;
  bipc::SourceFiles files;
  const std::uint32_t asn = files.add("test.asn");
  asn1::read_asn1("M DEFINITIONS AUTOMATIC TAGS ::= BEGIN\n" + spec.asn1 + "\nEND\n", asn, t.view,
                  diags);
  asn1::resolve(t.view, diags);
  const std::uint32_t pr = files.add("test.pr");
  sdl::SdlFile file = sdl::read_sdl(sdl, pr, diags);
  t.signature.name = "F";
  for (const auto& p : spec.provided)
    t.signature.provided.push_back(interface_of(p, t.view, diags));
  for (const auto& r : spec.required)
    t.signature.required.push_back(interface_of(r, t.view, diags));
  t.signature.context_timers = spec.timers;
  for (const ContextSpec& c : spec.context) {
    auto leaves = leaves_of(t.view, c.type, {}, diags);
    t.signature.context.push_back(
        ContextValue{c.name, c.type, c.value, leaves.value_or(std::vector<Leaf>{}), {}});
  }
  if (!diags.has_errors() && file.processes.size() == 1) {
    std::vector<const sdl::Procedure*> procedures;
    for (const sdl::Procedure& p : file.procedures) procedures.push_back(&p);
    static std::vector<sdl::SdlFile> kept;  // the atom's notes and locations outlive the call
    kept.push_back(std::move(file));
    t.atom = sdl_atom(t.signature, kept.back().processes[0], procedures, t.view, diags);
  }
  t.errors = diags.format(files);
  return t;
}

/// A call of provided interface `name` at `at_ms` with the BIP literals of its in leaves.
struct Call {
  double at_ms;
  std::string name;
  std::vector<std::string> values;
};

/// One interaction: its connector, its date (ms) and every scalar data after it (`f.x`).
struct Event {
  std::string connector;
  double time;
  std::map<std::string, double> data;
};

struct RunRecord {
  std::vector<Event> events;
  std::string output, trace;
  engines::RunResult result;
  /// The events of one connector.
  std::vector<Event> of(const std::string& connector) const {
    std::vector<Event> out;
    for (const Event& e : events) {
      if (e.connector == connector) out.push_back(e);
    }
    return out;
  }
};

class EventRecorder final : public engines::RunObserver {
 public:
  bool observe(const engines::StepInfo& step, const engines::StateView& state) override {
    if (step.fired != engines::StepInfo::Fired::Interaction) return true;
    const bipc::ir::System& system = state.system();
    Event e{system.connectors[step.connector].path, static_cast<double>(step.time) / 1e6, {}};
    for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
      const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
      for (bipc::ir::Index slot = 0; slot < type.data.size(); ++slot) {
        const engines::Val v = state.data(a, slot);
        double x = 0;
        switch (type.data[slot].type.kind) {
          case bipc::ir::ValueKind::Int:
            x = static_cast<double>(v.i);
            break;
          case bipc::ir::ValueKind::Bool:
            x = v.b ? 1 : 0;
            break;
          case bipc::ir::ValueKind::Float:
            x = v.f;
            break;
          default:
            continue;
        }
        e.data[system.atoms[a].path + "." + type.data[slot].name] = x;
      }
    }
    events.push_back(std::move(e));
    return true;
  }
  std::vector<Event> events;
};

inline std::string port_type_text(const std::string& name, const std::vector<std::string>& types) {
  std::string text = "  port type " + name + "(";
  for (std::size_t k = 0; k < types.size(); ++k) {
    text += (k ? ", " : "") + types[k] + " v" + std::to_string(k);
  }
  return text + ")\n  connector type Pass_" + name + "(" + name + " a, " + name +
         " b)\n    define a b\n" +
         [&] {
           if (types.empty()) return std::string();
           std::string down = "    on a b down {";
           for (std::size_t k = 0; k < types.size(); ++k) {
             down += " b.v" + std::to_string(k) + " = a.v" + std::to_string(k) + ";";
           }
           return down + " }\n";
         }() +
         "  end\n";
}

/// Declarations of `names` with `types`, and the list of the names for a port.
inline std::string data_of(const std::vector<std::string>& types, const std::string& prefix,
                           std::string& names) {
  std::string text;
  for (std::size_t k = 0; k < types.size(); ++k) {
    const std::string n = prefix + std::to_string(k);
    text += "    data " + types[k] + " " + n + "\n";
    names += (names.empty() ? "" : ", ") + n;
  }
  return text;
}

/// The driver `d`: it calls the provided interfaces of `t` on `script` (each call at its date,
/// the next after the return). Appends its connectors to `conns`.
inline std::string driver_of(const Translated& t, const std::vector<Call>& script,
                             std::string& conns) {
  std::string driver = "  atom type Driver()\n    clock t unit millisecond\n";
  for (const SignalInterface& p : t.signature.provided) {
    std::string in, ret;
    driver += data_of(p.data_types(false), p.name + "_a", in);
    driver += data_of(p.data_types(true), p.name + "_b", ret);
    driver += "    export port " + port_type_name(p.data_types(false)) + " call_" + p.name + "(" +
              in + ")\n    export port " + port_type_name(p.data_types(true)) + " ret_" + p.name +
              "(" + ret + ")\n";
    conns += "    connector Pass_" + port_type_name(p.data_types(false)) + " call_" + p.name +
             "(d.call_" + p.name + ", f." + p.name + "_in)\n    connector Pass_" +
             port_type_name(p.data_types(true)) + " ret_" + p.name + "(f." + p.name +
             "_return, d.ret_" + p.name + ")\n";
  }
  driver += "    place d0";
  for (std::size_t k = 0; k < script.size(); ++k) {
    driver += ", w" + std::to_string(k) + ", d" + std::to_string(k + 1);
  }
  // A port's data is read before its transition's statements: each call's values are set by
  // the step before it.
  auto values = [&](std::size_t k) {
    std::string out;
    for (std::size_t v = 0; k < script.size() && v < script[k].values.size(); ++v) {
      out += " " + script[k].name + "_a" + std::to_string(v) + " = " + script[k].values[v] + ";";
    }
    return out;
  };
  driver += "\n    initial to d0 do { t = 0;" + values(0) + " }\n";
  for (std::size_t k = 0; k < script.size(); ++k) {
    const Call& c = script[k];
    const std::string n = std::to_string(k);
    driver += "    on call_" + c.name + " from d" + n + " to w" + n +
              " provided (t >= " + std::to_string(c.at_ms) + ") eager\n    on ret_" + c.name +
              " from w" + n + " to d" + std::to_string(k + 1) + " eager do {" + values(k + 1) +
              " }\n";
  }
  return driver + "  end\n";
}

/// The sink `k`: it takes every call of the required interfaces of `t`, counts them, and
/// answers a synchronous one with ten times its first value. Appends its connectors to `conns`.
inline std::string sink_of(const Translated& t, std::string& conns) {
  std::string sink, transitions, places = "s";
  for (const SignalInterface& r : t.signature.required) {
    std::string out, res;
    sink += data_of(r.data_types(false), r.name + "_a", out);
    sink += data_of(r.data_types(true), r.name + "_b", res);
    sink += "    data int " + r.name + "_count = 0\n    export port " +
            port_type_name(r.data_types(false)) + " got_" + r.name + "(" + out + ")\n";
    conns += "    connector Pass_" + port_type_name(r.data_types(false)) + " out_" + r.name +
             "(f." + r.name + "_out, k.got_" + r.name + ")\n";
    std::string answer;  // set before `res` fires, which reads it
    for (std::size_t k = 0; r.synchronous() && k < r.data_types(true).size(); ++k) {
      answer += " " + r.name + "_b" + std::to_string(k) + " = " + r.name + "_a0 * 10;";
    }
    transitions += "    on got_" + r.name + " from s to " +
                   (r.synchronous() ? "s_" + r.name : "s") + " do { " + r.name +
                   "_count = " + r.name + "_count + 1;" + answer + " }\n";
    if (!r.synchronous()) continue;
    sink += "    export port " + port_type_name(r.data_types(true)) + " res_" + r.name + "(" + res +
            ")\n";
    places += ", s_" + r.name;
    transitions += "    on res_" + r.name + " from s_" + r.name + " to s eager\n";
    conns += "    connector Pass_" + port_type_name(r.data_types(true)) + " res_" + r.name +
             "(k.res_" + r.name + ", f." + r.name + "_result)\n";
  }
  return "  atom type Sink()\n" + sink + "    place " + places + "\n    initial to s\n" +
         transitions + "  end\n";
}

/// The package around the translated atom: driver `d` running `script`, sink `k`, atom `f`.
inline std::string package_of(const Translated& t, const std::vector<Call>& script) {
  std::vector<std::pair<std::string, std::vector<std::string>>> port_types = {{"Port", {}}};
  collect_port_types(t.signature, port_types);
  std::string text = "package sdltest\n";
  for (const auto& [name, types] : port_types) text += port_type_text(name, types);
  for (const std::string& f : t.atom->extern_functions) text += "  " + f + "\n";
  std::string conns;
  text += t.atom->text + driver_of(t, script, conns) + sink_of(t, conns);
  return text + "  compound type Top()\n    component F f()\n    component Driver d()\n" +
         "    component Sink k()\n" + conns + "  end\nend\n";
}

/// Runs the package of `t` for at most `steps` steps (seed 1).
inline RunRecord run_process(const Translated& t, const std::vector<Call>& script,
                             std::uint64_t steps = 200) {
  RunRecord record;
  if (!t.atom) {
    ADD_FAILURE() << "not translated:\n" << t.errors;
    return record;
  }
  const std::string package = package_of(t, script);
  const std::optional<bipc::ir::System> system = tests::load_model_text(package, "Top()");
  if (!system) {
    ADD_FAILURE() << package;
    return record;
  }
  engines::SimulateOptions options;
  options.seed = 1;
  options.limit = steps;
  engines::Simulator simulator(*system, options, engines::Externs::with_builtins());
  std::ostringstream trace, output;
  EventRecorder recorder;
  record.result = simulator.run(0, engines::RunStreams{trace, output}, &recorder);
  record.events = std::move(recorder.events);
  record.output = output.str();
  record.trace = trace.str();
  EXPECT_EQ(record.result.code, engines::kRunOk) << record.result.message << "\n" << package;
  return record;
}

}  // namespace smcbip::taste2bip::test
