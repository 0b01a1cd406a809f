// Reading a JSON-lines trace, and following it step by step.
#include "engines/api/replay.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "bipc/json_dump.h"
#include "engines/detail/replay_follower.h"
#include "engines/trace/text_trace.h"

namespace smcbip::engines {

namespace {

using Json = nlohmann::json;

ReplayStep read_step(const Json& line, std::size_t number, std::size_t expected,
                     const std::string& where) {
  ReplayStep step;
  step.line = number;
  if (!line.contains("step") || !line["step"].is_number_unsigned() ||
      line["step"].get<std::size_t>() != expected) {
    throw ReplayError(where, "expected step " + std::to_string(expected));
  }
  const Json& fired = line.value("fired", Json());
  if (expected > 0 && !fired.is_string()) {
    throw ReplayError(where, "step " + std::to_string(expected) + " names no fired interaction");
  }
  if (fired.is_string()) step.fired = fired.get<std::string>();
  if (line.contains("interaction") && line["interaction"].is_string()) {
    step.interaction = line["interaction"].get<std::string>();
  }
  if (line.contains("time") && line["time"].is_number()) step.time = line["time"].get<double>();
  if (line.contains("places")) {
    if (!line["places"].is_object()) throw ReplayError(where, "'places' is not an object");
    auto& places = step.places.emplace();
    for (const auto& [atom, marked] : line["places"].items()) {
      if (!marked.is_array()) throw ReplayError(where, "the places of " + atom + " are not a list");
      for (const Json& p : marked)
        places[atom].push_back(p.is_string() ? p.get<std::string>() : "");
    }
  }
  if (line.contains("data") && line["data"].is_object()) {
    for (const auto& [name, value] : line["data"].items()) step.data[name] = bipc::dump_json(value);
  }
  return step;
}

}  // namespace

ReplayScript read_replay_script(std::istream& in, const std::string& file) {
  ReplayScript script;
  script.file = file;
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    const std::string where = file + ":" + std::to_string(number);
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!script.end.empty()) throw ReplayError(where, "a line after the trace's end");
    Json line;
    try {
      line = Json::parse(text);
    } catch (const Json::parse_error& e) {
      throw ReplayError(where, std::string("not a JSON object: ") + e.what());
    }
    if (!line.is_object()) throw ReplayError(where, "not a JSON object");
    if (line.contains("header")) continue;
    if (line.contains("end")) {
      script.end = line["end"].is_string() ? line["end"].get<std::string>() : "error";
      script.end_line = number;
      continue;
    }
    script.steps.push_back(read_step(line, number, script.steps.size(), where));
  }
  if (script.steps.empty()) throw ReplayError(file, "the trace has no state");
  return script;
}

namespace detail {

namespace {

/// The connector or port an item fires, as the JSON-lines trace names it.
std::string fired_name(const Runtime& runtime, const Item& item) {
  const std::string text = item_text(runtime, item, false);
  if (item.kind != Item::Kind::Interaction) return text;
  return text.substr(0, text.find(": "));
}

/// A datum's value as the JSON-lines trace writes it.
std::string value_text(const StateView& state, Val v, bipc::ir::ValueKind kind) {
  switch (kind) {
    case bipc::ir::ValueKind::Bool:
      return bipc::dump_json(Json(v.b));
    case bipc::ir::ValueKind::Float:
      return bipc::dump_json(Json(v.f));
    case bipc::ir::ValueKind::String:
      return bipc::dump_json(Json(std::string(state.text(v))));
    case bipc::ir::ValueKind::Int:
      return bipc::dump_json(Json(v.i));
    default:
      return "null";
  }
}

}  // namespace

void ReplayFollower::fail(std::size_t line, const std::string& message) {
  if (failure_) return;
  failure_ = RunResult{kInputError, RunEnd::Error, next_ - 1, message,
                       script_.file + ":" + std::to_string(line)};
}

std::optional<std::size_t> ReplayFollower::pick(const Runtime& runtime) {
  if (next_ >= script_.steps.size()) {
    if (script_.end == "deadlock") {
      fail(script_.end_line, "the trace ends in a deadlock, but " +
                                 std::to_string(runtime.items().size()) +
                                 " interaction(s) are enabled");
    }
    return std::nullopt;
  }
  const ReplayStep& step = script_.steps[next_];
  std::string enabled;
  for (std::size_t i = 0; i < runtime.items().size(); ++i) {
    const Item& item = runtime.items()[i];
    const std::string text = item_text(runtime, item, false);
    const bool match = step.interaction.empty() ? fired_name(runtime, item) == step.fired
                                                : text == step.interaction;
    if (match) {
      date_.reset();
      if (step.time) date_ = static_cast<TimeValue>(std::llround(*step.time * 1e6));
      ++next_;
      return i;
    }
    enabled += (enabled.empty() ? "" : ", ") + text;
  }
  const std::string& wanted = step.interaction.empty() ? step.fired : step.interaction;
  fail(step.line, "step " + std::to_string(next_) + ": interaction " + wanted +
                      " is not enabled; enabled: " + enabled);
  return std::nullopt;
}

std::string ReplayFollower::compare(const ReplayStep& step, const StateView& state) const {
  const bipc::ir::System& system = state.system();
  std::set<std::string> atoms_seen;
  for (bipc::ir::Index a = 0; a < system.atoms.size(); ++a) {
    const bipc::ir::AtomType& type = system.atom_types[system.atoms[a].type];
    const std::string& name = state.atom_name(a);
    if (step.places) {
      atoms_seen.insert(name);
      std::vector<std::string> marked;
      for (bipc::ir::Index p = 0; p < type.places.size(); ++p) {
        if (state.marked(a, p)) marked.push_back(type.places[p]);
      }
      const auto recorded = step.places->find(name);
      if (recorded != step.places->end() && recorded->second != marked) {
        return "atom " + name + " marks " + (marked.empty() ? "no place" : marked.front()) +
               ", the trace " + (recorded->second.empty() ? "none" : recorded->second.front());
      }
    }
    for (bipc::ir::Index d = 0; d < type.data.size(); ++d) {
      const std::string path = name + "." + type.data[d].name;
      const auto recorded = step.data.find(path);
      if (recorded == step.data.end()) continue;
      const std::string actual = value_text(state, state.data(a, d), type.data[d].type.kind);
      if (actual != recorded->second) {
        return path + " is " + actual + ", the trace has " + recorded->second;
      }
    }
  }
  if (step.places) {
    for (const auto& [atom, marked] : *step.places) {
      if (!atoms_seen.contains(atom)) return "the model has no atom " + atom;
    }
  }
  return "";
}

bool ReplayFollower::observe(const StepInfo& step, const StateView& state) {
  if (step.step >= script_.steps.size()) return true;
  const ReplayStep& recorded = script_.steps[step.step];
  const std::string difference = compare(recorded, state);
  if (difference.empty()) return true;
  fail(recorded.line,
       "step " + std::to_string(step.step) + ": the state differs from the trace's: " + difference);
  return false;
}

void ReplayFollower::finish(RunEnd end, int /*code*/, const std::string& /*message*/) {
  if (failure_ || next_ >= script_.steps.size()) return;
  if (end != RunEnd::Deadlock && end != RunEnd::Timelock) return;
  const ReplayStep& step = script_.steps[next_];
  fail(step.line, "step " + std::to_string(next_) + ": interaction " +
                      (step.interaction.empty() ? step.fired : step.interaction) +
                      " is not enabled; enabled: none (" +
                      (end == RunEnd::Deadlock ? "deadlock" : "time-lock") + ")");
}

}  // namespace detail

}  // namespace smcbip::engines
