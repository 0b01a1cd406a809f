#include "engines/trace/jsonl_trace.h"

#include <nlohmann/json.hpp>

#include "bipc/json_dump.h"
#include "engines/semantics/layout.h"

namespace smcbip::engines {

namespace {

using Json = nlohmann::ordered_json;

Json value_json(const StateView& state, Val v, bipc::ir::ValueKind kind) {
  switch (kind) {
    case bipc::ir::ValueKind::Bool:
      return v.b;
    case bipc::ir::ValueKind::Float:
      return v.f;
    case bipc::ir::ValueKind::String:
      return std::string(state.text(v));
    case bipc::ir::ValueKind::Int:
      return v.i;
    default:
      return nullptr;  // extern data: opaque to the exchange format
  }
}

Json fired_json(const StepInfo& step, const StateView& state, const Layout& layout) {
  switch (step.fired) {
    case StepInfo::Fired::Interaction:
      return layout.connector_names[step.connector];
    case StepInfo::Fired::Internal:
    case StepInfo::Fired::External: {
      const auto& type = state.system().atom_types[state.system().atoms[step.atom].type];
      return state.atom_name(step.atom) + "." + type.ports[step.port].name;
    }
    default:
      return nullptr;
  }
}

const char* end_name(RunEnd end) {
  switch (end) {
    case RunEnd::Deadlock:
      return "deadlock";
    case RunEnd::Timelock:
      return "timelock";
    case RunEnd::Limit:
      return "limit";
    case RunEnd::Stopped:
      return "stopped";
    case RunEnd::Absorbing:
      return "absorbing";
    default:
      return "error";
  }
}

}  // namespace

double trace_time(TimeValue t) { return static_cast<double>(t) / 1e6; }

void JsonlTrace::header(const StateView& state) {
  Json clocks = Json::object();
  const bipc::ir::System& system = state.system();
  for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    for (const bipc::ir::Clock& clock : type.clocks) {
      clocks[state.atom_name(a) + "." + clock.name] = {{"unit_ns", nanoseconds_per(clock.unit)}};
    }
  }
  Json line;
  line["header"] = {{"format", "smcbip-trace"}, {"version", 1},      {"seed", seed_},
                    {"run", run_index_},        {"time_unit", "ms"}, {"clocks", std::move(clocks)}};
  out_ << bipc::dump_json(line) << '\n';
}

bool JsonlTrace::observe(const StepInfo& step, const StateView& state) {
  if (step.step == 0) header(state);
  Json places = Json::object();
  Json data = Json::object();
  Json rates = Json::object();
  const bipc::ir::System& system = state.system();
  for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    const std::string& name = state.atom_name(a);
    Json marked = Json::array();
    for (bipc::ir::Index p = 0; p < type.places.size(); ++p) {
      if (state.marked(a, p)) marked.push_back(type.places[p]);
    }
    places[name] = std::move(marked);
    for (bipc::ir::Index d = 0; d < type.data.size(); ++d) {
      data[name + "." + type.data[d].name] =
          value_json(state, state.data(a, d), type.data[d].type.kind);
    }
    for (bipc::ir::Index c = 0; c < type.clocks.size(); ++c) {
      data[name + "." + type.clocks[c].name] = state.clock(a, c);
      const double rate = state.clock_rate(a, c);
      if (rate != 1) rates[name + "." + type.clocks[c].name] = rate;
    }
  }
  Json line;
  line["step"] = step.step;
  line["time"] = trace_time(step.time);
  line["fired"] = fired_json(step, state, layout_);
  line["places"] = std::move(places);
  line["data"] = std::move(data);
  if (!rates.empty()) line["rates"] = std::move(rates);
  out_ << bipc::dump_json(line) << '\n';
  return true;
}

void JsonlTrace::finish(RunEnd end, int code, const std::string& message) {
  Json line;
  line["end"] = end_name(end);
  if (end == RunEnd::Error) {
    line["code"] = code;
    line["message"] = message;
  }
  out_ << bipc::dump_json(line) << '\n';
}

}  // namespace smcbip::engines
