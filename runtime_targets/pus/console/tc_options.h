// The syntax of one telecommand, shared by `pus-console encode`, script lines and the
// interactive mode: SERVICE SUBTYPE, the fields of the subtype, and the packet header options.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "packets/packets.h"

namespace smcbip::pus::console {

/// The words of one TC as given, before they are converted and checked.
struct TcWords {
  std::string service, subtype;
  std::vector<std::string> sids, events, pmons, params, args, releases, actions;
  std::optional<std::string> function, rate, apid, seq, source, ack;
  std::optional<std::string> repo, file, size, operation, to_repo, to_file;  ///< ST23
};

/// Registers SERVICE, SUBTYPE, the field options and the header options on a (sub)command;
/// values are kept as text so that build_tc can say what it expected of each.
void register_tc_options(CLI::App& app, TcWords& words);

/// The fields each subtype takes, for --help and the README.
std::string tc_syntax_help();

/// A word of a TC that cannot be converted: the option it was given to ("SERVICE",
/// "--apid", ...), the word itself ("" when the option itself is at fault: given to a subtype
/// without that field, or missing) and what was expected.
class TcSyntaxError : public std::runtime_error {
 public:
  TcSyntaxError(std::string option, std::string word, const std::string& message)
      : std::runtime_error(message), option_(std::move(option)), word_(std::move(word)) {}
  const std::string& option() const { return option_; }
  const std::string& word() const { return word_; }

 private:
  std::string option_, word_;
};

/// A converted TC, and whether its sequence count was given (a script numbers the others).
struct BuiltTc {
  Telecommand tc;
  bool seq_given = false;
};

/// Converts the words into a telecommand the packet library encodes under `config`; throws
/// TcSyntaxError naming the first word that does not fit.
BuiltTc build_tc(const TcWords& words, const Config& config);

/// Encodes a telecommand; throws TcSyntaxError (option "TC") if the library refuses it.
std::vector<std::uint8_t> encode_tc(const Telecommand& tc, const Config& config);

}  // namespace smcbip::pus::console
