#include "smc/tools/check_command.h"

#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "monitors/monitors.h"
#include "smc/tools/model_loading.h"

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

std::string number(double v) {
  std::ostringstream out;
  out << std::setprecision(6) << v;
  return out.str();
}

std::string query_text(const monitors::PropertyFile& file, const smc::QueryResult& r) {
  std::string text = to_string(file.queries[r.query]);
  for (const auto& [name, value] : r.parameters) text += " " + name + "=" + number(value);
  return text;
}

void print_table(const monitors::PropertyFile& file, const std::vector<smc::QueryResult>& rs) {
  for (const smc::QueryResult& r : rs) {
    std::cout << query_text(file, r) << "\n  " << smc::method_name(r.method) << ": ";
    if (!r.error.empty()) {
      std::cout << "no answer: " << r.error << "\n";
      continue;
    }
    if (r.verdict) std::cout << (*r.verdict ? "holds" : "does not hold") << ", ";
    std::cout << "estimate " << number(r.estimate);
    if (r.method != smc::Method::Sprt && r.method != smc::Method::Ssp) {
      std::cout << " in [" << number(r.ci.low) << ", " << number(r.ci.high) << "]";
    }
    std::cout << ", " << r.samples << " runs";
    if (r.undecided > 0) std::cout << " (" << r.undecided << " undecided)";
    std::cout << ", " << number(r.seconds) << " s\n";
  }
}

void print_json(const monitors::PropertyFile& file, const std::vector<smc::QueryResult>& rs) {
  using Json = nlohmann::ordered_json;
  Json results = Json::array();
  for (const smc::QueryResult& r : rs) {
    Json line;
    line["query"] = to_string(file.queries[r.query]);
    line["method"] = smc::method_name(r.method);
    line["param"] = Json::object();
    for (const auto& [name, value] : r.parameters) line["param"][name] = value;
    line["estimate"] = r.error.empty() ? Json(r.estimate) : Json(nullptr);
    line["ci"] = r.error.empty() ? Json::array({r.ci.low, r.ci.high}) : Json(nullptr);
    line["verdict"] = r.verdict ? Json(*r.verdict) : Json(nullptr);
    line["samples"] = r.samples;
    line["undecided"] = r.undecided;
    line["seconds"] = r.seconds;
    if (!r.error.empty()) line["error"] = r.error;
    results.push_back(std::move(line));
  }
  Json out;
  out["results"] = std::move(results);
  std::cout << out.dump(2) << "\n";
}

}  // namespace

void register_check_options(CLI::App& command, CheckCommand& check) {
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
  monitors::ParsedProperties parsed = monitors::load_properties(check.properties);
  if (parsed.ok()) monitors::resolve_names(parsed.file, *system, parsed.diagnostics);
  if (!parsed.ok()) {
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  }
  std::vector<smc::QueryResult> results;
  try {
    results = smc::check_properties(*system, parsed.file, check.options);
  } catch (const monitors::MonitorError& e) {
    parsed.diagnostics.error(e.at, e.what());
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return kInputError;
  } catch (const std::invalid_argument& e) {
    std::cerr << "smcbip: error: " << check.model.file << ": " << e.what() << "\n";
    return kInputError;
  }
  if (check.json) {
    print_json(parsed.file, results);
  } else {
    print_table(parsed.file, results);
  }
  int code = 0;
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
