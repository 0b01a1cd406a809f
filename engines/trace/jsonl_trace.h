// The JSON-lines trace exchange format (DESIGN.md): a header line declaring the run's seed and
// its clocks, one object per state, the initial one first, then an `end` line. Read back by
// `smcbip monitor` and by other tools.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "engines/api/run_observer.h"

namespace smcbip::engines {

class JsonlTrace : public RunObserver {
 public:
  /// Paths are the full names the text trace prints (`ROOT.a.b`), taken from `layout`; the
  /// header names the run by `seed` and `run_index`.
  JsonlTrace(std::ostream& out, const Layout& layout, std::uint64_t seed, std::uint64_t run_index)
      : out_(out), layout_(layout), seed_(seed), run_index_(run_index) {}

  bool observe(const StepInfo& step, const StateView& state) override;
  void finish(RunEnd end, int code, const std::string& message) override;

 private:
  /// The header line: the format, the seed and run index, and which data are clocks with
  /// their units (nanoseconds per unit); a step line gives the rates that are not 1.
  void header(const StateView& state);

  std::ostream& out_;
  const Layout& layout_;
  std::uint64_t seed_, run_index_;
};

/// A model date as the exchange format writes it: in milliseconds.
double trace_time(TimeValue t);

}  // namespace smcbip::engines
