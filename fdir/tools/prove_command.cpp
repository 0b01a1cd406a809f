// `smcbip prove`: loading, proving each query, and the report (human table or JSON).
#include "fdir/tools/prove_command.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "bipc/exit_codes.h"
#include "bipc/options.h"
#include "fdir/errors.h"
#include "fdir/tools/prove_trace.h"
#include "monitors/monitors.h"
#include "smc/tools/model_loading.h"

namespace smcbip::tools {

namespace {

using fdir::QueryOutcome;
using fdir::Verdict;

const char* verdict_text(Verdict v) {
  return v == Verdict::Holds ? "holds" : v == Verdict::Fails ? "fails" : "open";
}

void print_trace(std::ostream& out, const std::vector<fdir::TraceState>& trace) {
  for (std::size_t k = 0; k < trace.size(); ++k) {
    const fdir::TraceState& s = trace[k];
    out << "    " << k << ": " << (k == 0 ? "initial state" : s.fired) << "\n      places:";
    for (const std::string& p : s.places) out << " " << p;
    out << "\n";
    if (s.data.empty()) continue;
    out << "      data:";
    for (const auto& [name, value] : s.data) out << " " << name << "=" << value;
    out << "\n";
  }
}

/// `, under 2 assumptions` when the verdict rests on some.
std::string assumptions_text(const QueryOutcome& o) {
  if (o.assumptions.empty()) return "";
  const std::size_t n = o.assumptions.size();
  return ", under " + std::to_string(n) + (n == 1 ? " assumption" : " assumptions");
}

/// `1 trap`, `2 traps`.
std::string counted(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

/// What a candidate was checked against: every invariant the query's SMT check had.
std::string invariants_text(const QueryOutcome& o) {
  std::string text = "the component invariants (data invariants of " +
                     counted(o.component_invariants, "atom") + "), " + counted(o.traps, "trap");
  if (o.linear) {
    text += ", " + counted(o.place_invariants, "place invariant");
    if (o.state_equation) text += ", the state equation";
  }
  return text;
}

void print_outcome(std::ostream& out, const monitors::Query& q, const QueryOutcome& o) {
  out << monitors::to_string(q) << "  " << verdict_text(o.verdict) << " (" << o.method
      << assumptions_text(o) << "; traps " << o.traps << ", linear " << (o.linear ? "yes" : "no")
      << ", component invariants " << o.component_invariants << ", net transitions "
      << o.net_transitions << ")\n";
  if (!o.trace.empty()) {
    out << "  " << (q.kind == monitors::Query::Kind::Invariant ? "counterexample" : "witness")
        << " (" << o.trace.size() - 1 << (o.trace.size() == 2 ? " step" : " steps") << "):\n";
    print_trace(out, o.trace);
  }
  if (o.verdict == Verdict::Open) {
    out << "  candidate:";
    for (const std::string& c : o.candidate) out << " " << c;
    out << "\n  checked against: " << invariants_text(o) << "\n  " << o.note
        << "\n  an inductive assumption relating these places and data (--assume FILE.smt2, "
           "see docs/prove.md) may exclude it\n";
  }
}

nlohmann::json trace_json(const std::vector<fdir::TraceState>& trace) {
  nlohmann::json steps = nlohmann::json::array();
  for (std::size_t k = 0; k < trace.size(); ++k) {
    nlohmann::json data = nlohmann::json::object();
    for (const auto& [name, value] : trace[k].data) data[name] = value;
    steps.push_back({{"step", k},
                     {"fired", k == 0 ? nlohmann::json() : nlohmann::json(trace[k].fired)},
                     {"places", trace[k].places},
                     {"data", data}});
  }
  return steps;
}

nlohmann::json assumptions_json(const QueryOutcome& o) {
  nlohmann::json out = nlohmann::json::array();
  for (const fdir::AssumptionSite& a : o.assumptions) {
    out.push_back({{"file", a.file},
                   {"line", a.line},
                   {"column", a.column},
                   {"assertion", a.text},
                   {"inductive", true}});
  }
  return out;
}

nlohmann::json outcome_json(const monitors::Query& q, const QueryOutcome& o) {
  return {{"query", monitors::to_string(q)},
          {"verdict", verdict_text(o.verdict)},
          {"method", o.method},
          {"invariants",
           {{"traps", o.traps},
            {"linear", o.linear},
            {"place_invariants", o.place_invariants},
            {"state_equation", o.state_equation},
            {"component_invariants", o.component_invariants},
            {"net_transitions", o.net_transitions}}},
          {"assumptions", assumptions_json(o)},
          {"candidate", o.candidate},
          {"trace", trace_json(o.trace)},
          {"explored_states", o.explored_states},
          {"note", o.note},
          {"seconds",
           {{"invariants", o.seconds_invariants},
            {"smt", o.seconds_smt},
            {"search", o.seconds_search}}}};
}

/// An unsupported construct as a located error on stderr.
int report_unsupported(const fdir::UnsupportedModel& e, const bipc::ir::System& system,
                       const monitors::ParsedProperties& parsed, const std::string& model_file) {
  std::string where = model_file;
  if (e.at && e.in_property) {
    where = bipc::position_text(parsed.sources.path(e.at->file), e.at->line, e.at->column);
  } else if (e.at && e.at->file < system.source_files.size()) {
    where = bipc::position_text(system.source_files[e.at->file], e.at->line, e.at->column);
  }
  std::cerr << where << ": error: " << e.what() << "\n";
  return exit_codes::kInputError;
}

/// The assumption files' texts; nullopt (error printed) when one cannot be read.
std::optional<std::vector<fdir::AssumptionSource>> read_assumptions(
    const std::vector<std::string>& files) {
  std::vector<fdir::AssumptionSource> out;
  for (const std::string& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    if (in) text << in.rdbuf();
    if (!in) {
      std::cerr << file << ": error: cannot read the assumption file\n";
      return std::nullopt;
    }
    out.push_back({file, text.str()});
  }
  return out;
}

int report_assumption(const fdir::AssumptionError& e) {
  std::cerr << (e.line ? bipc::position_text(e.file, e.line, e.column) : e.file)
            << ": error: " << e.what() << "\n";
  return exit_codes::kInputError;
}

}  // namespace

void register_prove_options(CLI::App& command, ProveCommand& prove) {
  fdir::ProveOptions& o = prove.options;
  bipc::register_frontend_options(command, prove.model, true, "MODEL");
  command.add_option("PROP", prove.properties, "the property file: its A[] and E<> queries")
      ->required()
      ->type_name("");
  command
      .add_option("--explore-depth", o.explore_depth,
                  "steps from the initial state the search for a violating state goes")
      ->check(cli::integer_in(0, 1'000'000'000))
      ->option_text("K (default: " + std::to_string(o.explore_depth) + ")");
  command
      .add_option("--max-states", o.max_explored_states,
                  "states the search for a violating state keeps at most")
      ->check(cli::integer_in(1, 100'000'000))
      ->option_text("N (default: " + std::to_string(o.max_explored_states) + ")");
  command
      .add_option("--component-iterations", o.component_iterations,
                  "rounds of post-condition iteration per atom type (any number is sound)")
      ->check(cli::integer_in(0, 100))
      ->option_text("N (default: " + std::to_string(o.component_iterations) + ")");
  command
      .add_option_function<std::string>(
          "--method",
          [&o](const std::string& name) {
            o.method = name == "traps"    ? fdir::Method::Traps
                       : name == "linear" ? fdir::Method::Linear
                                          : fdir::Method::Both;
          },
          "interaction invariants: the traps of the net, its linear invariants (place "
          "invariants, state equation), or both")
      ->check(CLI::IsMember({"traps", "linear", "both"}).description(""))
      ->option_text(cli::choices_text({"traps", "linear", "both"}) + " (default: both)");
  command
      .add_option("--assume", prove.assumptions,
                  "an SMT-LIB2 file of assertions over the model's places and data, used once "
                  "shown inductive (repeatable)")
      ->type_name("FILE.smt2");
  command
      .add_option("--trace-out", prove.trace_out,
                  "write the first counterexample or witness as a JSON-lines trace, which "
                  "smcbip simulate --replay follows")
      ->type_name("FILE");
  cli::add_json_flag(command, prove.json);
  command.footer(
      "Priorities are dropped and clocks ignored by the invariants, which over-approximates the "
      "reachable states (sound). On a model with clocks no search for a counterexample is made: "
      "a candidate leaves the query open. Exit: 0 every query holds, 1 one does not, 4 one is "
      "left open, 2 bad input, 3 internal error. See docs/prove.md.");
}

int run_prove(const ProveCommand& prove) {
  LoadFailure failure{};
  const std::optional<bipc::ir::System> system = load_model_system(prove.model, failure);
  if (!system) return exit_codes::kInputError;
  monitors::ParsedProperties parsed = load_property_file(prove.properties);
  if (parsed.ok()) monitors::resolve_names(parsed.file, *system, parsed.diagnostics);
  for (const monitors::Query& q : parsed.file.queries) {
    if (q.kind != monitors::Query::Kind::Invariant && q.kind != monitors::Query::Kind::Reachable) {
      parsed.diagnostics.error(q.at,
                               "prove answers A[] and E<> queries only: smcbip check "
                               "answers the statistical ones");
    }
  }
  if (!parsed.ok()) {
    std::cerr << parsed.diagnostics.format(parsed.sources);
    return exit_codes::kInputError;
  }
  const monitors::Bindings constants = monitors::constant_values(parsed.file);
  const std::optional<std::vector<fdir::AssumptionSource>> assumptions =
      read_assumptions(prove.assumptions);
  if (!assumptions) return exit_codes::kInputError;
  std::vector<QueryOutcome> outcomes;
  try {
    fdir::Prover prover(*system, prove.options);
    prover.assume(*assumptions);
    for (const monitors::Query& q : parsed.file.queries) {
      outcomes.push_back(prover.prove(q, constants));
    }
  } catch (const fdir::UnsupportedModel& e) {
    return report_unsupported(e, *system, parsed, prove.model.file);
  } catch (const fdir::AssumptionError& e) {
    return report_assumption(e);
  }
  int code = 0;
  nlohmann::json all = nlohmann::json::array();
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const monitors::Query& q = parsed.file.queries[k];
    if (prove.json) all.push_back(outcome_json(q, outcomes[k]));
    if (!prove.json) print_outcome(std::cout, q, outcomes[k]);
    if (outcomes[k].verdict == Verdict::Fails) code = 1;
    if (outcomes[k].verdict == Verdict::Open && code == 0) code = kProveOpen;
  }
  if (prove.json)
    std::cout << nlohmann::json{{"model", prove.model.file}, {"queries", all}}.dump(2) << "\n";
  if (!prove.trace_out.empty()) {
    const auto traced = std::find_if(outcomes.begin(), outcomes.end(),
                                     [](const QueryOutcome& o) { return !o.trace.empty(); });
    if (traced == outcomes.end()) {
      std::cerr << "smcbip: no query has a counterexample or witness: " << prove.trace_out
                << " is not written\n";
    } else if (const int failed = write_prove_trace(prove.trace_out, *system, traced->trace)) {
      return failed;
    }
  }
  return code;
}

}  // namespace smcbip::tools
