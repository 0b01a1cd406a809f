#include "smc/tools/monitor_command.h"

#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bipc/exit_codes.h"
#include "bipc/input_file.h"
#include "bipc/json_dump.h"
#include "bipc/options.h"
#include "monitors/monitors.h"
#include "smc/tools/model_loading.h"
#include "smc/tools/report.h"

namespace smcbip::tools {
namespace {

using monitors::TraceReport;
using monitors::TraceResult;
using monitors::Verdict;

using exit_codes::kInputError;
constexpr int kFails = exit_codes::kPropertyFails;

/// Nanosecond ticks per unit of the traces' times.
const std::map<std::string, double> kTicksPerUnit{
    {"s", 1e9}, {"ms", 1e6}, {"us", 1e3}, {"ns", 1.0}};

const char* verdict_text(Verdict v) {
  return v == Verdict::True ? "true" : v == Verdict::False ? "false" : "undecided";
}

std::string result_text(const TraceResult& r) {
  if (r.value) return number_text(*r.value, 12);
  return verdict_text(r.verdict);
}

std::string parameters_text(const monitors::Bindings& parameters) {
  std::string text;
  for (const auto& [name, value] : parameters) {
    text += (text.empty() ? "  (" : ", ") + name + " = " + number_text(value, 12);
  }
  return text.empty() ? text : text + ")";
}

struct Checked {
  std::string path;
  TraceReport report;
};

void print_table(const monitors::PropertyFile& file, const std::vector<Checked>& checked) {
  for (const Checked& c : checked) {
    std::cout << c.path << ": " << c.report.steps << " steps, "
              << (c.report.end.empty() ? "no end line" : c.report.end) << "\n";
    for (const TraceResult& r : c.report.results) {
      std::string value = result_text(r);
      value.resize(std::max<std::size_t>(value.size(), 10), ' ');
      std::cout << "  " << value << " " << to_string(file.queries[r.query])
                << parameters_text(r.parameters) << "\n";
    }
  }
}

void print_json(const monitors::PropertyFile& file, const std::vector<Checked>& checked) {
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  for (const Checked& c : checked) {
    for (const TraceResult& r : c.report.results) {
      nlohmann::ordered_json line;
      line["trace"] = c.path;
      line["query"] = to_string(file.queries[r.query]);
      line["param"] = nlohmann::ordered_json::object();
      for (const auto& [name, value] : r.parameters) line["param"][name] = value;
      if (r.value) {
        line["value"] = *r.value;
        line["verdict"] = nullptr;
      } else {
        line["verdict"] = r.verdict == Verdict::Undecided
                              ? nlohmann::ordered_json(nullptr)
                              : nlohmann::ordered_json(r.verdict == Verdict::True);
      }
      line["steps"] = c.report.steps;
      line["end"] = c.report.end.empty() ? nlohmann::ordered_json(nullptr)
                                         : nlohmann::ordered_json(c.report.end);
      results.push_back(std::move(line));
    }
  }
  nlohmann::ordered_json out;
  out["results"] = std::move(results);
  std::cout << bipc::dump_json(out, 2) << "\n";
}

/// Resolves the properties' names against the model of --model (errors into `parsed`); false
/// when the model itself does not load (reported).
bool names_of_model(const MonitorOptions& options, monitors::ParsedProperties& parsed) {
  LoadFailure failure{};
  const std::optional<bipc::ir::System> system = load_model_system(options.model, failure);
  if (!system) return false;
  monitors::resolve_names(parsed.file, *system, parsed.diagnostics);
  return true;
}

}  // namespace

void register_monitor_options(CLI::App& command, MonitorOptions& options) {
  command.add_option("PROP", options.properties, "the property file (.mtl or .ltl)")
      ->required()
      ->type_name("");
  cli::once_per_use(command.add_option("--trace", options.traces,
                                       "a recorded run in the JSON-lines format (repeatable)"))
      ->required()
      ->type_name("RUN.jsonl");
  cli::add_json_flag(command, options.json);
  command.add_flag("--pointwise", options.pointwise,
                   "read time at steps only (default: continuously, a state holding until the "
                   "next step)");
  command
      .add_option("--time-unit", options.time_unit,
                  "the unit of the traces' times and of bounds written without one")
      ->check(CLI::IsMember({"s", "ms", "us", "ns"}).description(""))
      ->option_text(cli::choices_text({"s", "ms", "us", "ns"}) + " (default: ms)");
  command
      .add_option("--model", options.model.file,
                  "the model the runs come from: the properties' names must be its own")
      ->type_name("FILE");
  bipc::register_model_options(command, options.model);
}

int run_monitor(const MonitorOptions& options) {
  monitors::ParsedProperties parsed = load_property_file(options.properties);
  if (parsed.ok() && !options.model.file.empty() && !names_of_model(options, parsed)) {
    return kInputError;
  }
  if (!parsed.ok()) {
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  }
  const monitors::TimeScale scale{kTicksPerUnit.at(options.time_unit), 1e9};
  std::vector<Checked> checked;
  for (const std::string& path : options.traces) {
    bipc::require_input_file(path, "the trace", /*streams=*/true);
    std::ifstream in(path);
    if (!in) {
      std::cerr << "smcbip: error: cannot read the trace " << path << "\n";
      return kInputError;
    }
    bipc::Diagnostics diagnostics;
    try {
      const monitors::Reading reading =
          options.pointwise ? monitors::Reading::Pointwise : monitors::Reading::Continuous;
      checked.push_back(
          {path, monitors::check_trace(parsed.file, in, path, scale, diagnostics, reading)});
    } catch (const monitors::TraceError& e) {
      std::cerr << e.report();
      return kInputError;
    } catch (const monitors::MonitorError& e) {
      diagnostics.error(e.at, e.what());
    }
    if (diagnostics.has_errors()) {
      std::cerr << diagnostics.format(parsed.sources);
      return kInputError;
    }
  }
  if (options.json) {
    print_json(parsed.file, checked);
  } else {
    print_table(parsed.file, checked);
  }
  for (const Checked& c : checked) {
    for (const TraceResult& r : c.report.results) {
      if (!r.value && r.verdict == Verdict::False) return kFails;
    }
  }
  return 0;
}

}  // namespace smcbip::tools
