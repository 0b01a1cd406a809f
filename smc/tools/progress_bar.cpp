#include "smc/tools/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string_view>

namespace smcbip::tools {
namespace {

constexpr int kBarWidth = 24;

/// A bar of kBarWidth cells, the first `fraction` of them full.
std::string bar(double fraction) {
  const int full = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kBarWidth));
  return "[" + std::string(full, '#') + std::string(kBarWidth - full, '.') + "]";
}

/// SPRT's ratio between its thresholds: accept at the left, reject at the right.
std::string test_scale(double position) {
  const int at = static_cast<int>(std::lround(position * (kBarWidth - 1)));
  std::string scale(kBarWidth, '-');
  scale[at] = '*';
  return "accept |" + scale + "| reject";
}

}  // namespace

bool stderr_is_terminal() {
  const char* term = std::getenv("TERM");
  return ::isatty(STDERR_FILENO) == 1 && !(term && std::string_view(term) == "dumb");
}

std::string ProgressBar::line(const smc::Progress& p) const {
  std::ostringstream out;
  out << "query " << p.query + 1 << "/" << queries_;
  if (p.points > 1) out << ", " << p.points - p.open << "/" << p.points << " points done";
  out << "  ";
  const double rate = p.seconds > 0 ? static_cast<double>(p.runs) / p.seconds : 0;
  if (p.target > 0) {
    out << bar(static_cast<double>(p.runs) / static_cast<double>(p.target)) << " " << p.runs << "/"
        << p.target << " runs";
  } else if (p.test_position >= 0) {
    out << test_scale(p.test_position) << " " << p.runs << " runs";
  } else {
    out << p.runs << " runs";
  }
  out << std::setprecision(4) << "  p~" << p.estimate << "  " << std::fixed << std::setprecision(0)
      << rate << " runs/s";
  if (p.target > p.runs && rate > 0) {
    out << std::setprecision(1) << "  " << static_cast<double>(p.target - p.runs) / rate
        << " s left";
  }
  return out.str();
}

void ProgressBar::show(const smc::Progress& p) {
  out_ << "\r" << line(p) << "\x1b[K" << std::flush;
  drawn_ = true;
}

void ProgressBar::clear() {
  if (!drawn_) return;
  out_ << "\r\x1b[K" << std::flush;
  drawn_ = false;
}

}  // namespace smcbip::tools
