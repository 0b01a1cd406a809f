// The JSON-lines trace exchange format (DESIGN.md): one object per state, the initial one first,
// then an `end` line. Read back by `smcbip monitor` and by other tools.
#pragma once

#include <ostream>
#include <string>

#include "engines/run_observer.h"

namespace smcbip::engines {

class JsonlTrace : public RunObserver {
 public:
  /// Paths are the full names the text trace prints (`ROOT.a.b`), taken from `layout`.
  JsonlTrace(std::ostream& out, const Layout& layout) : out_(out), layout_(layout) {}

  bool observe(const StepInfo& step, const StateView& state) override;
  void finish(RunEnd end, int code, const std::string& message) override;

 private:
  std::ostream& out_;
  const Layout& layout_;
};

/// A model date as the exchange format writes it: in milliseconds.
double trace_time(TimeValue t);

}  // namespace smcbip::engines
