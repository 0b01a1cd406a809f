// The progress line `smcbip check` and `explore` keep on stderr when it is a terminal.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "smc/check/check.h"

namespace smcbip::tools {

/// Whether stderr is a terminal that can redraw a line.
bool stderr_is_terminal();

/// Draws progress reports over one another on one line, and wipes it when done.
class ProgressBar {
 public:
  ProgressBar(std::ostream& out, std::size_t queries) : out_(out), queries_(queries) {}
  ~ProgressBar() { clear(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void show(const smc::Progress& p);
  void clear();

  /// The line for `p`, without terminal controls.
  std::string line(const smc::Progress& p) const;

 private:
  std::ostream& out_;
  std::size_t queries_;
  bool drawn_ = false;
};

}  // namespace smcbip::tools
