#include "smc/tools/check_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <thread>

#include "bipc/exit_codes.h"
#include "bipc/ir/model_hash.h"
#include "bipc/options.h"
#include "bipc/output_file.h"
#include "engines/api/plugin.h"
#include "monitors/monitors.h"
#include "smc/tools/automatic_compile.h"
#include "smc/tools/first_hit_plot.h"
#include "smc/tools/model_loading.h"
#include "smc/tools/progress_bar.h"
#include "smc/tools/report.h"
#include "smc/tools/sweep_plot.h"
#include "smc/tools/trajectory_plot.h"

namespace smcbip::tools {
namespace {

using exit_codes::kInputError;
constexpr int kFails = exit_codes::kPropertyFails;

/// --param: the most values a range may give (each is a point judged at every run).
constexpr double kMaxParameterValues = 100'000;

/// Refuses a --param range start:stop:step of more than kMaxParameterValues values (or of
/// numbers that are not finite), before the property parser would list them all; other
/// mistakes are the parser's to report.
std::string sweep_size(std::string& text) {
  const auto equals = text.find('=');
  const std::string values = equals == std::string::npos ? "" : text.substr(equals + 1);
  double start = 0, stop = 0, step = 0;
  char end = 0;
  if (std::sscanf(values.c_str(), "%lf:%lf:%lf%c", &start, &stop, &step, &end) != 3) return {};
  if (!std::isfinite(start) || !std::isfinite(stop) || !std::isfinite(step)) {
    return "'" + text + "': the range's numbers must be finite";
  }
  if (step > 0 && stop >= start && (stop - start) / step + 1 > kMaxParameterValues) {
    return "'" + text + "' gives more than " + number_text(kMaxParameterValues) +
           " values: take a larger step";
  }
  return {};
}

/// --max-steps: a run's steps, below any count that could wrap.
constexpr std::uint64_t kMaxStepsPerRun = std::uint64_t{1} << 62;

const std::map<std::string, smc::Method> kMethods{
    {"auto", smc::Method::Auto},     {"sprt", smc::Method::Sprt}, {"ssp", smc::Method::Ssp},
    {"pestim", smc::Method::Pestim}, {"ci", smc::Method::Ci},     {"bayes", smc::Method::Bayes}};
const std::map<std::string, smc::UndecidedPolicy> kPolicies{{"fail", smc::UndecidedPolicy::Fail},
                                                            {"skip", smc::UndecidedPolicy::Skip},
                                                            {"error", smc::UndecidedPolicy::Error}};

/// Whether the files to write can be written once the answers are known: their folders exist
/// and they are (or link to) regular files or nothing yet.
bool writable_outputs(const CheckCommand& check) {
  if (!check.trajectories.empty() && !std::filesystem::is_directory(check.trajectories)) {
    std::cerr << "smcbip: error: --trajectories: no folder " << check.trajectories << "\n";
    return false;
  }
  for (const std::string& path : {check.plot, check.csv}) {
    if (path.empty()) continue;
    std::string target, error;
    if (!bipc::output_target(path, target, error)) {
      std::cerr << "smcbip: error: " << error << "\n";
      return false;
    }
    const std::filesystem::path folder = std::filesystem::path(target).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder)) {
      std::cerr << "smcbip: error: " << path << ": no folder " << folder.string() << "\n";
      return false;
    }
  }
  return true;
}

/// Whether `name` is the name of a trace --save-traces keeps (query-<q>-run-<i>.jsonl).
bool is_saved_trace(const std::string& name) {
  return name.starts_with("query-") && name.ends_with(".jsonl") &&
         name.find("-run-") != std::string::npos;
}

/// The folder of --save-traces, made if missing; refused when it holds traces already, as
/// they would mix with this command's.
bool trace_folder(const CheckCommand& check) {
  const std::string& folder = check.options.save_traces;
  if (folder.empty()) return true;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder)) {
    std::cerr << "smcbip: error: --save-traces: cannot make the folder " << folder
              << (error ? ": " + error.message() : "") << "\n";
    return false;
  }
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (!is_saved_trace(name)) continue;
    std::cerr << "smcbip: error: --save-traces: " << folder << " already holds traces (" << name
              << "); give an empty or new folder\n";
    return false;
  }
  if (!error) return true;
  std::cerr << "smcbip: error: --save-traces: cannot read the folder " << folder << ": "
            << error.message() << "\n";
  return false;
}

/// Whether check's plot draws `q`: an estimate of F phi within a time bound.
bool first_hit_plotted(const monitors::Query& q) {
  if (q.kind != monitors::Query::Kind::Estimate || !q.formula ||
      q.formula->kind != monitors::Formula::Kind::Finally) {
    return false;
  }
  return q.run.kind == monitors::Bound::Kind::Time ||
         q.formula->bound.kind == monitors::Bound::Kind::Time;
}

/// `--plot` needs what it draws: explore a query over a parameter, check an estimate of F phi
/// within a time bound (UPPAAL's Pr[<=T](<> phi)).
bool plottable(CheckCommand& check, const monitors::PropertyFile& file) {
  if (check.plot.empty()) return true;
  if (!check.explore) {
    for (const monitors::Query& q : file.queries) {
      if (first_hit_plotted(q)) check.options.first_hits = true;
    }
    if (check.options.first_hits) return true;
    std::cerr << "smcbip: error: --plot: no query of " << check.properties
              << " estimates when a formula first holds (Pr[<=T](<> phi) or P=? [ F[0,T] phi ])\n";
    return false;
  }
  for (const monitors::Query& q : file.queries) {
    if (sweeps_parameter(file, q)) return true;
  }
  std::cerr << "smcbip: error: --plot: no query of " << check.properties
            << " names a parameter (declare one with param, or give --param NAME=values)\n";
  return false;
}

const std::map<std::string, CompileMode> kCompileModes{
    {"auto", CompileMode::Auto}, {"always", CompileMode::Always}, {"never", CompileMode::Never}};

/// The plugin of --compiled, if given, once it is known to hold the model `hash` names (one
/// that cannot be loaded throws engines::PluginError, an InputError); else the one --compile
/// takes from the cache of compiled models, if any. MPI ranks run interpreted unless given
/// --compiled, so that all make their runs alike.
bool load_compiled(CheckCommand& check, const bipc::ir::System& system,
                   const bipc::ir::ExternSources& externs, const monitors::PropertyFile& file,
                   const std::string& hash) {
  if (check.compiled.empty()) {
    if (check.remote != nullptr) return true;
    const std::string root = check.model.root.empty() ? system.root_type : check.model.root;
    check.options.compiled = compiled_model(kCompileModes.at(check.compile),
                                            {&system, check.model.file, root, hash, externs}, file,
                                            check.options, check.explore, std::cerr);
    return true;
  }
  const engines::Plugin plugin = engines::load_plugin(check.compiled);
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
  if (!check.plot.empty()) {
    write(check.plot, check.explore ? sweep_svg(report) : first_hit_svg(report));
  }
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
  bipc::register_frontend_options(command, check.model, true, "MODEL");
  command.add_option("PROP", check.properties, "the property file (.mtl or .ltl)")
      ->required()
      ->type_name("");
  command.add_option("--method", check.method, "sprt or ssp (hypotheses), pestim, ci or bayes")
      ->check(CLI::IsMember({"auto", "sprt", "ssp", "pestim", "ci", "bayes"}).description(""))
      ->option_text(cli::choices_text({"auto", "sprt", "ssp", "pestim", "ci", "bayes"}) +
                    " (default: auto)");
  const auto probability = [&](const std::string& name, double& value, const std::string& help,
                               double low, double high) {
    // The bounds as people read them: 1 - 1e-12 is "1)", an open end.
    const std::string shown_high = high < 1 && 1 - high < 1e-9 ? "1)" : number_text(high) + "]";
    command.add_option(name, value, help)
        ->check(cli::finite_in(low, high))
        ->option_text("X in [" + number_text(low) + ", " + shown_high +
                      " (default: " + number_text(value) + ")");
  };
  probability("--alpha", o.alpha, "error bound: false rejections, or 1 - confidence", 1e-12, 0.5);
  probability("--beta", o.beta, "error bound: false acceptances", 1e-12, 0.5);
  probability("--delta", o.delta, "half-width of the indifference region or interval", 1e-6, 0.5);
  probability("--confidence", o.confidence, "Bayesian coverage; expectations' intervals", 0.5,
              1 - 1e-12);
  cli::add_seed_option(command, o.seed, "the seed of the runs' random streams (default: 1)");
  o.threads = std::min(std::max(1u, std::thread::hardware_concurrency()), cli::max_threads());
  cli::add_threads_option(command, o.threads, "threads making runs, all cores by default", 1);
  command
      .add_option("--max-steps", o.max_steps,
                  "steps a run may take at most (default: " + std::to_string(o.max_steps) + ")")
      ->check(cli::integer_in(1, kMaxStepsPerRun))
      ->type_name("K");
  cli::add_json_flag(command, check.json);
  command
      .add_option("--compiled", check.compiled,
                  "run the model compiled by bipc gen (its plugin, or the folder of its built "
                  "project), which must be MODEL")
      ->type_name("DIR");
  command
      .add_option("--compile", check.compile,
                  "run the model's generated code, built once into the cache of compiled models "
                  "($SMCBIP_CACHE_DIR, else ~/.cache/smcbip): auto when the interpreted runs "
                  "are expected to take longer than the build, always, or never (a cached "
                  "build is used unless never; --compiled wins)")
      ->check(CLI::IsMember({"auto", "always", "never"}).description(""))
      ->option_text(cli::choices_text({"auto", "always", "never"}) + " (default: auto)");
  command
      .add_option("--save-traces", o.save_traces,
                  "keep the trace of every run the answers took in this folder (JSON lines); "
                  "a folder that holds earlier traces is refused")
      ->type_name("DIR");
  cli::once_per_use(command.add_option("--param", check.parameters,
                                       "a parameter's values, NAME=start:stop:step or "
                                       "NAME={v1,v2,...} (replaces the file's declaration of "
                                       "NAME; repeatable)"))
      ->type_name("NAME=VALUES")
      ->check(CLI::Validator(sweep_size, "", "sweep_size"));
  if (!explore) {
    command
        .add_option("--plot", check.plot,
                    "write when F phi first holds in the runs of each estimate of it within a "
                    "time bound (Pr[<=T](<> phi)): the cumulative probability with its band and "
                    "the density, as SVG, to this file")
        ->type_name("FILE");
  }
  if (explore) {
    command.add_option("--plot", check.plot, "write the sweeps' plot (SVG) to this file")
        ->type_name("FILE");
    command.add_option("--csv", check.csv, "write the results as CSV to this file")
        ->type_name("FILE");
  }
  command
      .add_option("--trajectories", check.trajectories,
                  "write the trajectories of simulate queries to this folder "
                  "(simulate-LINE.csv and .svg)")
      ->type_name("DIR");
  command
      .add_option("--undecided", check.undecided,
                  "runs the monitor leaves undecided: fail (count as false), skip (draw others, "
                  "giving up after " +
                      std::to_string(smc::kMaxSkippedRuns) +
                      " when they outnumber the decided), error (skip up to 1% of the runs)")
      ->check(CLI::IsMember({"fail", "skip", "error"}).description(""))
      ->option_text(cli::choices_text({"fail", "skip", "error"}) + " (default: error)");
}

int run_check(CheckCommand check) {
  check.options.method = kMethods.at(check.method);
  check.options.undecided = kPolicies.at(check.undecided);
  LoadFailure failure{};
  const std::optional<bipc::ir::System> system = load_model_system(check.model, failure);
  if (!system) return kInputError;
  monitors::ParsedProperties parsed = load_property_file(check.properties, check.parameters);
  if (parsed.ok()) monitors::resolve_names(parsed.file, *system, parsed.diagnostics);
  if (!parsed.ok()) {
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  }
  if (parsed.file.queries.empty()) {
    // Nothing to answer is a mistake (the wrong file, every query commented out), not a
    // success with no output.
    std::cerr << check.properties << ": error: the property file holds no query to answer\n";
    return kInputError;
  }
  if (!plottable(check, parsed.file) || !writable_outputs(check) || !trace_folder(check)) {
    return kInputError;
  }
  // An extern source that cannot be read throws ExternSourceError, an InputError.
  const bipc::ir::ExternSources externs =
      bipc::ir::extern_sources_of(*system, check.model.include_dirs);
  const std::string hash = bipc::ir::model_hash(*system, externs);
  check.options.remote = check.remote;
  if (!load_compiled(check, *system, externs, parsed.file, hash)) return kInputError;
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
    std::cerr << check.model.file << ": error: " << e.what() << "\n";
    return kInputError;
  }
  if (progress) progress->clear();
  if (check.worker) return 0;  // rank 0 reports
  const Report report{parsed.file,
                      results,
                      check.model.file,
                      system->root_name,
                      hash,
                      {check.method, check.undecided, &check.options, check.parameters}};
  if (check.json) {
    std::cout << json_text(report);
  } else if (check.explore) {
    print_sweeps(std::cout, report);
  } else {
    print_results(std::cout, report);
  }
  int code = write_outputs(check, report) ? 0 : kInputError;
  // Each query without an answer at its line in the property file; a model error that made
  // runs undecided at the model file as well.
  bipc::Diagnostics unanswered;
  std::string model_errors;
  for (const smc::QueryResult& r : results) {
    if (!r.error.empty()) {
      const monitors::Query& q = parsed.file.queries[r.query];
      unanswered.error(q.at, to_string(q) + ": " + r.error);
      code = kInputError;
    } else if (r.verdict && !*r.verdict && code == 0) {
      code = kFails;
    }
    const smc::UndecidedRuns& why = r.why_undecided;
    if (why.error > 0 && model_errors.empty()) {
      // Answered all the same (skipped runs): a warning, so that no model error goes unseen.
      model_errors = check.model.file + (r.error.empty() ? ": warning: run " : ": error: run ") +
                     std::to_string(why.first_error_run) +
                     " ended in an error: " + why.first_error + "\n";
    }
  }
  std::cerr << unanswered.format(parsed.sources) << model_errors;
  return code;
}

}  // namespace smcbip::tools
