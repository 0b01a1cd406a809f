// Diagnostic collection and the `file:line:col: error: ...` rendering.
#include "bipc/diagnostics.h"

#include <algorithm>
#include <tuple>

namespace smcbip::bipc {

std::uint32_t SourceFiles::add(const std::string& path) {
  auto found = std::find(paths.begin(), paths.end(), path);
  if (found != paths.end()) return static_cast<std::uint32_t>(found - paths.begin());
  paths.push_back(path);
  return static_cast<std::uint32_t>(paths.size() - 1);
}

void Diagnostics::error(Location at, std::string message) {
  items_.push_back({Severity::Error, at, std::move(message)});
  ++error_count_;
}

void Diagnostics::warning(Location at, std::string message) {
  items_.push_back({Severity::Warning, at, std::move(message)});
}

void Diagnostics::note(Location at, std::string message) {
  items_.push_back({Severity::Note, at, std::move(message)});
}

void Diagnostics::sort_by_location() {
  // A note belongs to the diagnostic before it: groups move together, so that a note pointing at
  // an earlier line still follows the error it explains.
  std::vector<std::vector<Diagnostic>> groups;
  for (Diagnostic& d : items_) {
    if (d.severity != Severity::Note || groups.empty()) groups.emplace_back();
    groups.back().push_back(std::move(d));
  }
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    const Location& x = a.front().location;
    const Location& y = b.front().location;
    return std::tie(x.file, x.line, x.column) < std::tie(y.file, y.line, y.column);
  });
  items_.clear();
  for (std::vector<Diagnostic>& group : groups) {
    for (Diagnostic& d : group) items_.push_back(std::move(d));
  }
}

namespace {
const char* severity_name(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}
}  // namespace

std::string position_text(const std::string& path, std::uint64_t line, std::uint64_t column) {
  return path + ":" + std::to_string(line) + ":" + std::to_string(column);
}

std::string Diagnostics::format(const SourceFiles& files) const {
  std::string out;
  for (const Diagnostic& d : items_) {
    const std::string& path = d.location.file < files.paths.size() ? files.paths[d.location.file]
                                                                   : std::string("<input>");
    out += position_text(path, d.location.line, d.location.column) + ": " +
           severity_name(d.severity) + ": " + d.message + "\n";
  }
  return out;
}

}  // namespace smcbip::bipc
