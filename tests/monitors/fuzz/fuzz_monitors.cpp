// Property files and JSON-lines traces driven from memory, for the fuzzers and their replay.
#include "fuzz_monitors.h"

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "bipc/bipc.h"
#include "monitors/monitors.h"

namespace smcbip::monitors::fuzz {
namespace {

/// The model the properties' names are resolved against (models/channel.bip), or null when it
/// does not load.
const bipc::ir::System* channel_model() {
  static const std::optional<bipc::ir::System> system = [] {
    bipc::FrontendResult result =
        bipc::run_frontend({std::string(SMCBIP_SOURCE_DIR) + "/models/channel.bip", {}, ""}, true);
    return std::move(result.system);
  }();
  return system ? &*system : nullptr;
}

/// Milliseconds in the traces, nanosecond ticks: what `smcbip monitor` uses by default.
constexpr TimeScale kMilliseconds{1e6, 1e9};

/// Properties that bind to any trace: they name no data or place.
constexpr const char* kFiredProperties =
    "const k = 2\n"
    "param t = {0, 2, 10}\n"
    "P=? [ F[0,10] fired(send) ]\n"
    "P=? [ G[0,t] !fired(Sys.ack) ]\n"
    "P>=0.5 [ true U[2,2] fired(send) ]\n"
    "P=? [ F[0,t] fired(ROOT.request) ]\n"
    "P=? [ X X X (true || fired(a.b)) ]\n"
    "Pr[#<=3](F fired(send))\n"
    "Pr[<=k](G !fired(send))\n";

/// A parsed property file that must be valid, for the checks of the traces.
ParsedProperties must_parse(const std::string& text) {
  ParsedProperties parsed = parse_properties(text, "fuzz.mtl");
  if (!parsed.ok()) {
    std::fprintf(stderr, "fixed properties do not parse:\n%s",
                 parsed.diagnostics.format(parsed.sources).c_str());
    std::abort();
  }
  return parsed;
}

/// Whether `name` is a dotted path of identifiers, so that the properties built from it are
/// read as the name the trace meant.
bool plain_path(const std::string& name) {
  bool start = true;
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    const bool digit = c >= '0' && c <= '9';
    if (c == '.' && !start) {
      start = true;
    } else if (letter || (digit && !start)) {
      start = false;
    } else {
      return false;
    }
  }
  return !name.empty() && !start && name.size() < 200;
}

/// Properties over a data and a place of the trace's first line, or "" when it names none.
std::string properties_of_first_line(std::string_view text) {
  const nlohmann::json first =
      nlohmann::json::parse(text.substr(0, text.find('\n')), nullptr, /*allow_exceptions=*/false);
  if (!first.is_object()) return "";
  std::string data, place;
  if (const auto d = first.find("data"); d != first.end() && d->is_object()) {
    for (const auto& [key, value] : d->items()) {
      if (plain_path(key) && (value.is_number() || value.is_boolean())) {
        data = key;
        break;
      }
    }
  }
  if (const auto p = first.find("places"); p != first.end() && p->is_object()) {
    for (const auto& [atom, marked] : p->items()) {
      if (!marked.is_array() || marked.empty() || !marked[0].is_string()) continue;
      const std::string path = atom + "." + marked[0].get<std::string>();
      if (plain_path(path)) {
        place = path;
        break;
      }
    }
  }
  std::string out = "param t = {1, 5, 50}\n";
  if (!data.empty()) {
    out += "P=? [ F[0,10] " + data + " > 0 ]\n";
    out += "P=? [ G[0,t] " + data + " >= 0 ]\n";
    out += "P=? [ (" + data + " < 3) U[1,20] fired(send) ]\n";
    out += "Pr[<=9](F " + data + " == 2)\n";
    out += "E=? [ max: " + data + " ]\n";
    out += "E[<=100; 10](min: " + data + " * 2)\n";
  }
  if (!place.empty()) {
    out += "P=? [ F[0,t] " + place + " ]\n";
    out += "P>=0.5 [ X X " + place + " ]\n";
    out += "Pr[#<=5](G !" + place + ")\n";
  }
  return data.empty() && place.empty() ? "" : out;
}

/// Judges the trace against `parsed` in both readings; trace and monitor errors are expected.
void judge(const ParsedProperties& parsed, std::string_view text) {
  for (const Reading reading : {Reading::Continuous, Reading::Pointwise}) {
    std::istringstream in{std::string(text)};
    bipc::Diagnostics diagnostics;
    try {
      (void)check_trace(parsed.file, in, "fuzz.jsonl", kMilliseconds, diagnostics, reading);
    } catch (const TraceError& e) {
      (void)e.what();
    } catch (const MonitorError& e) {
      (void)e.what();
    }
  }
}

}  // namespace

void run_properties_on(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ParsedProperties parsed = parse_properties(text, "fuzz.mtl");
  if (!parsed.ok()) {
    (void)parsed.diagnostics.format(parsed.sources);
    return;
  }
  for (const Declaration& d : parsed.file.declarations) (void)to_string(d);
  for (const Query& q : parsed.file.queries) (void)to_string(q);
  if (const bipc::ir::System* model = channel_model()) {
    resolve_names(parsed.file, *model, parsed.diagnostics);
    (void)parsed.diagnostics.format(parsed.sources);
  }
}

void run_trace_on(const std::uint8_t* data, std::size_t size) {
  static const ParsedProperties fired = must_parse(kFiredProperties);
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  judge(fired, text);
  const std::string own = properties_of_first_line(text);
  if (own.empty()) return;
  // A name may still be a keyword of the language ("F", "max"): such traces get the fixed ones.
  const ParsedProperties parsed = parse_properties(own, "fuzz.mtl");
  if (parsed.ok()) judge(parsed, text);
}

}  // namespace smcbip::monitors::fuzz
