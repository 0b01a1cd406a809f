// The errors of the user's making that tools report (bad option, unreadable or invalid input),
// with where they were found; internal faults stay std::exception.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace smcbip {

/// Where an error was found: a file (or option, as `--seed`), and when known a line and column
/// (1-based; 0: unknown).
struct ErrorLocation {
  std::string file;
  std::uint32_t line = 0, column = 0;
};

/// An error of the user's making; what() is the message without its location.
class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& message, ErrorLocation at = {})
      : std::runtime_error(message), at_(std::move(at)) {}
  const ErrorLocation& at() const { return at_; }
  /// `file:line:col: error: message` (as much of the location as is known), or
  /// `tool: error: message` without one.
  std::string describe(const std::string& tool) const {
    std::string where = at_.file.empty() ? tool : at_.file;
    if (!at_.file.empty() && at_.line > 0) {
      where += ":" + std::to_string(at_.line);
      if (at_.column > 0) where += ":" + std::to_string(at_.column);
    }
    return where + ": error: " + what();
  }

 private:
  ErrorLocation at_;
};

/// A command line the tool cannot act on: a bad option value, a missing argument.
class UsageError : public UserError {
 public:
  using UserError::UserError;
};

/// Input the tool cannot read or accept: a model, a property file, a file to write.
class InputError : public UserError {
 public:
  using UserError::UserError;
};

}  // namespace smcbip
