#include "smc/tools/check_command.h"

#include <filesystem>
#include <iostream>
#include <map>
#include <thread>

#include "bipc/ir/model_hash.h"
#include "bipc/output_file.h"
#include "engines/plugin.h"
#include "monitors/monitors.h"
#include "smc/tools/model_loading.h"
#include "smc/tools/progress_bar.h"
#include "smc/tools/report.h"
#include "smc/tools/sweep_plot.h"
#include "smc/tools/trajectory_plot.h"

namespace smcbip::tools {
namespace {

constexpr int kFails = 1;
constexpr int kInputError = 2;

const std::map<std::string, smc::Method> kMethods{
    {"auto", smc::Method::Auto},     {"sprt", smc::Method::Sprt}, {"ssp", smc::Method::Ssp},
    {"pestim", smc::Method::Pestim}, {"ci", smc::Method::Ci},     {"bayes", smc::Method::Bayes}};
const std::map<std::string, smc::UndecidedPolicy> kPolicies{{"fail", smc::UndecidedPolicy::Fail},
                                                            {"skip", smc::UndecidedPolicy::Skip},
                                                            {"error", smc::UndecidedPolicy::Error}};

/// Whether the files to write can be written once the answers are known: their folders exist.
bool writable_outputs(const CheckCommand& check) {
  if (!check.trajectories.empty() && !std::filesystem::is_directory(check.trajectories)) {
    std::cerr << "smcbip: error: --trajectories: no folder " << check.trajectories << "\n";
    return false;
  }
  for (const std::string& path : {check.plot, check.csv}) {
    if (path.empty()) continue;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder)) {
      std::cerr << "smcbip: error: " << path << ": no folder " << folder.string() << "\n";
      return false;
    }
  }
  return true;
}

/// The folder of --save-traces, made if missing.
bool trace_folder(const CheckCommand& check) {
  if (check.options.save_traces.empty()) return true;
  std::error_code error;
  std::filesystem::create_directories(check.options.save_traces, error);
  if (!error && std::filesystem::is_directory(check.options.save_traces)) return true;
  std::cerr << "smcbip: error: --save-traces: cannot make the folder " << check.options.save_traces
            << (error ? ": " + error.message() : "") << "\n";
  return false;
}

/// `--plot` needs a query over a parameter.
bool plottable(const CheckCommand& check, const monitors::PropertyFile& file) {
  if (check.plot.empty()) return true;
  for (const monitors::Query& q : file.queries) {
    if (sweeps_parameter(file, q)) return true;
  }
  std::cerr << "smcbip: error: --plot: no query of " << check.properties
            << " names a parameter (declare one with param, or give --param NAME=values)\n";
  return false;
}

std::optional<std::string> hash_of(const bipc::ir::System& system, const CheckCommand& check) {
  try {
    return bipc::ir::model_hash(system,
                                bipc::ir::extern_sources_of(system, check.model.include_dirs));
  } catch (const bipc::ir::ExternSourceError& e) {
    std::cerr << "smcbip: error: extern source " << e.path << ": " << e.message << "\n";
    return std::nullopt;
  }
}

/// The plugin of --compiled, if given, once it is known to hold the model `hash` names.
bool load_compiled(CheckCommand& check, const std::string& hash) {
  if (check.compiled.empty()) return true;
  engines::Plugin plugin;
  try {
    plugin = engines::load_plugin(check.compiled);
  } catch (const engines::PluginError& e) {
    std::cerr << "smcbip: error: --compiled: " << e.message << "\n";
    return false;
  }
  if (hash != plugin.entry->model_hash) {
    std::cerr << "smcbip: error: " << plugin.path << " holds another model (hash "
              << plugin.entry->model_hash << ") than " << check.model.file << " (hash " << hash
              << "); generate and build it again\n";
    return false;
  }
  check.options.compiled = plugin.entry;
  return true;
}

bool write_outputs(const CheckCommand& check, const Report& report) {
  bool ok = true;
  const auto write = [&](const std::string& path, const std::string& text) {
    std::string error;
    if (path.empty() || bipc::write_file_atomically(path, text, error)) return;
    std::cerr << "smcbip: error: " << error << "\n";
    ok = false;
  };
  write(check.csv, check.csv.empty() ? "" : csv_text(report));
  write(check.plot, check.plot.empty() ? "" : sweep_svg(report));
  if (check.trajectories.empty()) return ok;
  for (const smc::QueryResult& r : report.results) {
    if (!r.trajectories) continue;
    // Named by the query's line, with the parameters' values when it has any.
    std::string name = "simulate-" + std::to_string(report.file.queries[r.query].at.line);
    for (const auto& [parameter, value] : r.parameters) {
      name += "-" + parameter + "=" + number_text(value);
    }
    const std::filesystem::path base = std::filesystem::path(check.trajectories) / name;
    write(base.string() + ".csv", trajectories_csv(*r.trajectories));
    write(base.string() + ".svg",
          trajectories_svg(to_string(report.file.queries[r.query]), *r.trajectories));
  }
  return ok;
}

}  // namespace

void register_check_options(CLI::App& command, CheckCommand& check, bool explore) {
  check.explore = explore;
  smc::CheckOptions& o = check.options;
  command.add_option("MODEL", check.model.file, "the BIP model")->required();
  command.add_option("PROP", check.properties, "the property file (.mtl or .ltl)")->required();
  command.add_option("--root", check.model.root, "the model's root compound");
  command.add_option("-I", check.model.include_dirs, "a folder of packages the model uses");
  command.add_option("--method", check.method, "sprt or ssp (hypotheses), pestim, ci or bayes")
      ->check(CLI::IsMember({"auto", "sprt", "ssp", "pestim", "ci", "bayes"}))
      ->capture_default_str();
  command.add_option("--alpha", o.alpha, "error bound: false rejections, or 1 - confidence")
      ->check(CLI::Range(1e-12, 0.5))
      ->capture_default_str();
  command.add_option("--beta", o.beta, "error bound: false acceptances")
      ->check(CLI::Range(1e-12, 0.5))
      ->capture_default_str();
  command.add_option("--delta", o.delta, "half-width of the indifference region or interval")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  command.add_option("--confidence", o.confidence, "Bayesian coverage; expectations' intervals")
      ->check(CLI::Range(0.5, 1 - 1e-12))
      ->capture_default_str();
  command.add_option("--seed", o.seed, "the seed of the runs' random streams")
      ->capture_default_str();
  o.threads = std::max(1u, std::thread::hardware_concurrency());
  command.add_option("--threads", o.threads, "threads making runs (default: all cores)")
      ->check(CLI::Range(1u, 1024u));
  command.add_option("--max-steps", o.max_steps, "steps a run may take at most")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 62))
      ->capture_default_str();
  command.add_flag("--json", check.json, "print the results as one JSON object");
  command.add_option("--compiled", check.compiled,
                     "run the model compiled by bipc gen (its plugin, or the folder of its built "
                     "project), which must be MODEL");
  command.add_option("--save-traces", o.save_traces,
                     "keep the trace of every run the answers took in this folder (JSON lines)");
  command.add_option("--param", check.parameters,
                     "a parameter's values, NAME=start:stop:step or NAME={v1,v2,...} (replaces "
                     "the file's declaration of NAME)");
  if (explore) {
    command.add_option("--plot", check.plot, "write the sweeps' plot (SVG) to this file");
    command.add_option("--csv", check.csv, "write the results as CSV to this file");
  }
  command.add_option("--trajectories", check.trajectories,
                     "write the trajectories of simulate queries to this folder "
                     "(simulate-LINE.csv and .svg)");
  command
      .add_option("--undecided", check.undecided,
                  "undecided runs: fail (count as false), skip (not counted), error (skipped "
                  "up to 1% of the runs)")
      ->check(CLI::IsMember({"fail", "skip", "error"}))
      ->capture_default_str();
}

int run_check(CheckCommand check) {
  check.options.method = kMethods.at(check.method);
  check.options.undecided = kPolicies.at(check.undecided);
  LoadFailure failure{};
  const std::optional<bipc::ir::System> system = load_model_system(check.model, failure);
  if (!system) return kInputError;
  monitors::ParsedProperties parsed = monitors::load_properties(check.properties, check.parameters);
  if (parsed.ok()) monitors::resolve_names(parsed.file, *system, parsed.diagnostics);
  if (!parsed.ok()) {
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  }
  if (!plottable(check, parsed.file) || !writable_outputs(check) || !trace_folder(check)) {
    return kInputError;
  }
  const std::optional<std::string> hash = hash_of(*system, check);
  if (!hash || !load_compiled(check, *hash)) return kInputError;
  check.options.remote = check.remote;
  std::optional<ProgressBar> progress;
  if (!check.worker && stderr_is_terminal()) {
    progress.emplace(std::cerr, parsed.file.queries.size());
    check.options.progress = [&](const smc::Progress& p) { progress->show(p); };
  }
  std::vector<smc::QueryResult> results;
  try {
    results = check.explore ? smc::explore_properties(*system, parsed.file, check.options)
                            : smc::check_properties(*system, parsed.file, check.options);
  } catch (const monitors::MonitorError& e) {
    progress.reset();
    parsed.diagnostics.error(e.at, e.what());
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  } catch (const std::invalid_argument& e) {
    progress.reset();
    std::cerr << "smcbip: error: " << check.model.file << ": " << e.what() << "\n";
    return kInputError;
  }
  if (progress) progress->clear();
  if (check.worker) return 0;  // rank 0 reports
  const Report report{parsed.file, results, check.model.file, system->root_name, *hash};
  if (check.json) {
    std::cout << json_text(report);
  } else if (check.explore) {
    print_sweeps(std::cout, report);
  } else {
    print_results(std::cout, report);
  }
  int code = write_outputs(check, report) ? 0 : kInputError;
  for (const smc::QueryResult& r : results) {
    if (!r.error.empty()) {
      std::cerr << "smcbip: error: " << to_string(parsed.file.queries[r.query]) << ": " << r.error
                << "\n";
      code = kInputError;
    } else if (r.verdict && !*r.verdict && code == 0) {
      code = kFails;
    }
  }
  return code;
}

}  // namespace smcbip::tools
