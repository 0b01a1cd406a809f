// Source locations and diagnostics shared by every stage of the front end.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace smcbip::bipc {

/// A position in a loaded source file; `file` indexes SourceFiles, line and column are 1-based.
struct Location {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

/// `path:line:column`, as every located message begins.
std::string position_text(const std::string& path, std::uint64_t line, std::uint64_t column);

/// The files read while loading a model; a Location's `file` indexes `paths`.
struct SourceFiles {
  std::vector<std::string> paths;
  /// Registers a path and returns its index (the same index for the same path).
  std::uint32_t add(const std::string& path);
  const std::string& path(std::uint32_t file) const { return paths.at(file); }
};

enum class Severity { Error, Warning, Note };

/// One message about the model, pointing at the offending source position.
struct Diagnostic {
  Severity severity = Severity::Error;
  Location location;
  std::string message;
};

/// Collects diagnostics; stages never print, the command-line tool decides how to show them.
class Diagnostics {
 public:
  void error(Location at, std::string message);
  void warning(Location at, std::string message);
  void note(Location at, std::string message);

  bool has_errors() const { return error_count_ > 0; }
  std::size_t error_count() const { return error_count_; }
  const std::vector<Diagnostic>& all() const { return items_; }
  /// Sorts by file, line, column (stable), so output follows the source; notes stay after the
  /// diagnostic they follow.
  void sort_by_location();

  /// `file:line:col: error: message`, one per line.
  std::string format(const SourceFiles& files) const;

 private:
  std::vector<Diagnostic> items_;
  std::size_t error_count_ = 0;
};

}  // namespace smcbip::bipc
