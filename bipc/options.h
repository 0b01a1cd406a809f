// Command-line options, declared once and shared by every tool: those of the front end (the
// model file, -I/--include, --root) and the conventions of all tools (numbers checked as
// written, --seed, --threads, --json, --version).
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "bipc/bipc.h"

#ifndef SMCBIP_VERSION_TEXT
#define SMCBIP_VERSION_TEXT "unknown"
#endif

namespace smcbip::cli {

/// The most threads a tool starts: 4 per hardware thread, never more than 256 (a larger
/// number only costs memory and switches).
inline unsigned max_threads() {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  return std::min(256u, 4 * hardware);
}

/// Checks that an option's text is a decimal integer in [low, high] (no sign, no octal or hex:
/// C's strtoull would take "-1" as 2^64-1 and "010" as 8).
inline CLI::Validator integer_in(std::uint64_t low, std::uint64_t high) {
  const std::string range =
      "an integer from " + std::to_string(low) + " to " + std::to_string(high);
  return CLI::Validator(
      [low, high, range](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == text.npos;
        if (!digits || error != std::errc() || stop != end || value < low || value > high) {
          return "'" + text + "' is not " + range;
        }
        return {};
      },
      "", "integer_in");
}

/// Checks that an option's text is a finite number in [low, high] (NaN and infinities, which
/// compare false with every bound, are refused by name).
inline CLI::Validator finite_in(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        char* stop = nullptr;
        const double value = std::strtod(text.c_str(), &stop);
        if (text.empty() || stop != text.c_str() + text.size()) {
          return "'" + text + "' is not a number";
        }
        if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
        if (value < low || value > high) {
          return "'" + text + "' is not in [" + CLI::detail::to_string(low) + ", " +
                 CLI::detail::to_string(high) + "]";
        }
        return {};
      },
      "", "finite_in");
}

/// An option that takes one value per use and never takes the arguments after it: `-I A -I B
/// FILE` gives A and B, and FILE stays a positional argument.
inline CLI::Option* once_per_use(CLI::Option* option) {
  return option->expected(1)->allow_extra_args(false)->multi_option_policy(
      CLI::MultiOptionPolicy::TakeAll);
}

/// --seed: a 64-bit seed, written in decimal.
template <typename Seed>
CLI::Option* add_seed_option(CLI::App& app, Seed& seed, const std::string& help) {
  return app.add_option("--seed", seed, help)
      ->check(integer_in(0, std::numeric_limits<std::uint64_t>::max()))
      ->type_name("N");
}

/// --threads: from `least` to max_threads().
inline CLI::Option* add_threads_option(CLI::App& app, unsigned& threads, const std::string& help,
                                       unsigned least) {
  const std::string bound =
      "at most " + std::to_string(max_threads()) + " here: 4 per hardware thread, 256 in all";
  return app.add_option("--threads", threads, help + " (" + bound + ")")
      ->check(CLI::Validator(
          [least, bound](std::string& text) -> std::string {
            std::string error = integer_in(least, max_threads())(text);
            if (error.empty()) return {};
            return "'" + text + "' is not a number of threads from " + std::to_string(least) +
                   " (" + bound + ")";
          },
          "", "threads"))
      ->type_name("N");
}

/// --json: results as one JSON object on stdout.
inline CLI::Option* add_json_flag(CLI::App& app, bool& json) {
  return app.add_flag("--json", json, "print the results as one JSON object");
}

/// --version on a command and on each of its subcommands.
inline void add_version_flags(CLI::App& app, const std::string& tool) {
  const std::string text = tool == "smcbip" ? tool + " " SMCBIP_VERSION_TEXT
                                            : tool + " (smcbip " SMCBIP_VERSION_TEXT ")";
  app.set_version_flag("--version", text, "print the version and exit");
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->set_version_flag("--version", text, "print the version and exit");
  }
}

/// An enumeration's option lists its names in --help, not CLI11's mapping to numbers.
inline std::string choices_text(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : "|") + name;
  return text;
}

/// The transform of an enumeration's option: a name of `names` (any case) becomes its value, and
/// any other word is refused with the names (CLI11's CheckedTransformer says "Check x value in
/// {a->,b->}", which no one should have to read).
template <class Enum>
CLI::Validator named_choice(const std::map<std::string, Enum>& names) {
  std::string listing;
  for (const auto& entry : names) listing += (listing.empty() ? "" : ", ") + entry.first;
  return CLI::Validator(
      [names, listing](std::string& input) -> std::string {
        std::string lower = input;
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        const auto found = names.find(lower);
        if (found == names.end()) return "'" + input + "' is not one of " + listing;
        input = std::to_string(static_cast<std::underlying_type_t<Enum>>(found->second));
        return {};
      },
      "");
}

}  // namespace smcbip::cli

namespace smcbip::bipc {

/// The call a --root names: `Top` alone means the constructor without arguments, `Top()`.
inline std::string root_call(const std::string& root) {
  const auto first = root.find_first_not_of(" \t");
  if (first == std::string::npos || root.find('(') != std::string::npos) return root;
  const auto last = root.find_last_not_of(" \t");
  return root.substr(first, last - first + 1) + "()";
}

/// Registers -I/--include (one folder per use, repeatable) and --root on a (sub)command.
inline void register_model_options(CLI::App& app, FrontendOptions& options) {
  cli::once_per_use(app.add_option("-I,--include", options.include_dirs,
                                   "a folder searched for used packages (repeatable, one per use)"))
      ->type_name("DIR");
  app.add_option("--root", options.root,
                 "the root instance: 'Syst()', 'pkg.Top(3)', or a type name alone for its "
                 "constructor without arguments")
      ->type_name("CALL")
      ->transform([](const std::string& root) { return root_call(root); }, "", "root_call");
}

/// Registers the model file as the positional argument `name` (required unless
/// `file_required` is false), -I/--include and --root on a (sub)command.
inline void register_frontend_options(CLI::App& app, FrontendOptions& options,
                                      bool file_required = true, const std::string& name = "FILE") {
  app.add_option(name, options.file, "the BIP2 package file (.bip)")
      ->required(file_required)
      ->type_name("");
  register_model_options(app, options);
}

}  // namespace smcbip::bipc
