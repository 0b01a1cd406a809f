// Oracles over reference-engine traces, and the harness that runs conformance models.
#include "tests/engines/trace_oracles.h"

#include <algorithm>
#include <charconv>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "bipc/bipc.h"
#include "engines/api/externs.h"
#include "tests/bipc/shared_data.h"
#include "tests/engines/conformance_externs.h"

namespace smcbip::tests {
namespace {

constexpr std::string_view kPrefix = "[BIP ENGINE]: ";
constexpr std::string_view kHeaderStart = "[BIP ENGINE]: state #";
constexpr std::string_view kListingStart = "[BIP ENGINE]:   [";
constexpr std::string_view kChooseStart = "[BIP ENGINE]: -> choose ";

std::regex basic_regex(const std::string& pattern) {
  return std::regex(pattern, std::regex::basic);
}

bool matches(const std::regex& re, const std::string& line) { return std::regex_search(line, re); }

/// Parses `line` as a state header; nullopt when it is not one.
std::optional<StateHeader> parse_header(const std::string& line, std::size_t index) {
  const std::string_view text = line;
  if (!text.starts_with(kHeaderStart)) return std::nullopt;
  std::string_view rest = text.substr(kHeaderStart.size());
  StateHeader header;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), header.state);
  if (error != std::errc() || end == rest.data()) return std::nullopt;
  rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
  constexpr std::string_view kTime = " and global time ";
  if (!rest.starts_with(kTime)) return std::nullopt;
  rest.remove_prefix(kTime.size());
  // Time values contain neither blanks nor colons, so the first ": " ends the time.
  const std::size_t colon = rest.find(": ");
  if (colon == std::string_view::npos) return std::nullopt;
  header.time = std::string(rest.substr(0, colon));
  header.summary = std::string(rest.substr(colon + 2));
  header.line = index;
  return header;
}

}  // namespace

Lines split_lines(std::string_view text) {
  Lines lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (line.ends_with('\r')) line.remove_suffix(1);
    lines.emplace_back(line);
    start = end + 1;
  }
  return lines;
}

bool has(const Lines& lines, const std::string& pattern) {
  const std::regex re = basic_regex(pattern);
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& line) { return matches(re, line); });
}

std::size_t count(const Lines& lines, const std::string& pattern) {
  const std::regex re = basic_regex(pattern);
  return static_cast<std::size_t>(std::count_if(
      lines.begin(), lines.end(), [&](const std::string& line) { return matches(re, line); }));
}

bool lacks(const Lines& lines, const std::string& pattern) { return !has(lines, pattern); }

bool tail_has(const Lines& lines, std::size_t k, const std::string& pattern) {
  const std::regex re = basic_regex(pattern);
  const std::size_t first = lines.size() > k ? lines.size() - k : 0;
  return std::any_of(lines.begin() + static_cast<std::ptrdiff_t>(first), lines.end(),
                     [&](const std::string& line) { return matches(re, line); });
}

std::vector<StateHeader> state_headers(const Lines& lines) {
  std::vector<StateHeader> headers;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (auto header = parse_header(lines[i], i)) headers.push_back(std::move(*header));
  }
  return headers;
}

std::optional<StateHeader> find_state_header(const Lines& lines, std::uint64_t n) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    auto header = parse_header(lines[i], i);
    if (header && header->state == n) return header;
  }
  return std::nullopt;
}

std::string state_header(const Lines& lines, std::uint64_t n) {
  auto header = find_state_header(lines, n);
  if (!header) return "<no state #" + std::to_string(n) + ">";
  return std::move(header->summary);
}

std::string state_time(const Lines& lines, std::uint64_t n) {
  auto header = find_state_header(lines, n);
  if (!header) return "<no state #" + std::to_string(n) + ">";
  return std::move(header->time);
}

std::string last_state_header(const Lines& lines) {
  for (std::size_t i = lines.size(); i-- > 0;) {
    if (auto header = parse_header(lines[i], i)) return std::move(header->summary);
  }
  return "<no state header>";
}

Lines listing(const Lines& lines, std::uint64_t n) {
  Lines result;
  const auto header = find_state_header(lines, n);
  if (!header) return result;
  for (std::size_t i = header->line + 1;
       i < lines.size() && std::string_view(lines[i]).starts_with(kListingStart); ++i) {
    result.push_back(lines[i]);
  }
  return result;
}

Lines choose_lines(const Lines& lines) {
  Lines result;
  std::copy_if(lines.begin(), lines.end(), std::back_inserter(result), [](const std::string& line) {
    return std::string_view(line).starts_with(kChooseStart);
  });
  return result;
}

std::optional<ExplorationSummary> exploration_summary(const Lines& lines) {
  static const std::regex re(
      R"(computing reachable states:.*found ([0-9]+) reachable states?, ([0-9]+) deadlocks?, )"
      R"(([0-9]+) timelocks?, and ([0-9]+) errors? in ([0-9]+) states?)");
  for (const std::string& line : lines) {
    std::smatch m;
    if (!std::regex_search(line, m, re)) continue;
    ExplorationSummary summary;
    summary.states = std::stoull(m[1].str());
    summary.deadlocks = std::stoull(m[2].str());
    summary.timelocks = std::stoull(m[3].str());
    summary.errors = std::stoull(m[4].str());
    summary.error_states = std::stoull(m[5].str());
    return summary;
  }
  return std::nullopt;
}

std::string describe_difference(const Lines& actual, const Lines& expected) {
  const std::size_t common = std::min(actual.size(), expected.size());
  for (std::size_t i = 0; i < common; ++i) {
    if (actual[i] != expected[i]) {
      return "line " + std::to_string(i + 1) + " is\n  \"" + actual[i] + "\"\nexpected\n  \"" +
             expected[i] + "\"";
    }
  }
  if (actual.size() == expected.size()) return {};
  if (actual.size() > expected.size()) {
    return std::to_string(actual.size()) + " lines where " + std::to_string(expected.size()) +
           " were expected; first extra line: \"" + actual[common] + "\"";
  }
  return std::to_string(actual.size()) + " lines where " + std::to_string(expected.size()) +
         " were expected; first missing line: \"" + expected[common] + "\"";
}

std::string error_line_pattern(int code) {
  const std::string error = "^\\[BIP ENGINE]: ERROR: ";  // a lone `]` is plain in BRE
  switch (code) {
    case engines::kNonDeterministicNet:
      return error + "non-deterministic choice between ";
    case engines::kNonOneSafeNet:
      return error + "the .* net of .* is not 1-safe!";
    case engines::kCycleInPriorities:
    case engines::kCycleInAtomPriorities:
      return error + "cycle in priorities! (";
    case engines::kInvariantViolation:
      return error + "the invariant .* of component .* has been violated!";
    case engines::kUnexpectedEvent:
      return error + "port .* of component .* has received ";
    case engines::kTimeSafetyViolation:
      return error + ".*violation of the following timing constraints:";
    default:
      throw std::invalid_argument("no error line for run code " + std::to_string(code));
  }
}

std::filesystem::path conformance_dir() {
  return bipc::test::shared_data_dir() / "bip-conformance";
}

std::optional<bipc::ir::System> load_conformance_model(const std::string& model,
                                                       const std::string& root) {
  const std::filesystem::path file = conformance_dir() / (model + ".bip");
  bipc::FrontendOptions options;
  options.file = file.string();
  options.include_dirs = {file.parent_path().string()};
  options.root = root;
  bipc::FrontendResult result = bipc::run_frontend(options, true);
  if (!result.system || result.diags.has_errors()) {
    ADD_FAILURE() << "front end rejected " << file.string() << " with root " << root << ":\n"
                  << result.diags.format(result.model.files);
    return std::nullopt;
  }
  return std::move(result.system);
}

ConformanceRun run_conformance(const bipc::ir::System& system,
                               const engines::SimulateOptions& options) {
  return run_conformance(engines::InterpretedModel(system), options);
}

ConformanceRun run_conformance(const engines::Model& model,
                               const engines::SimulateOptions& options) {
  engines::Externs externs = engines::Externs::with_builtins();
  register_conformance_externs(externs);
  std::ostringstream out;
  ConformanceRun run;
  engines::Simulator simulator(model, options, externs);
  run.result = simulator.run(options.run_index, engines::RunStreams{out, out});
  run.text = std::move(out).str();
  run.lines = split_lines(run.text);
  return run;
}

void expect_run_error(const ConformanceRun& run, int code) {
  EXPECT_EQ(run.result.code, code);
  EXPECT_TRUE(has(run.lines, error_line_pattern(code)))
      << "no error line matching " << error_line_pattern(code) << " in:\n"
      << run.text;
}

}  // namespace smcbip::tests
