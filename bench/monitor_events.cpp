// The online monitor's speed and memory on long traces: future-time versions of the
// timescales patterns (absence, universality, recurrence, response after Ulus, RV 2019) with
// their bounds scaled 1x, 10x and 100x, and punctual until `p U[n,n] q` for n = 1,000 to
// 10,000. Each trace has one event per time unit and satisfies its pattern at every point
// (as timescales' traces do), so no verdict cuts a run short; the until traces are random,
// under a disjunction with r, true throughout, that keeps the run going while the until
// works. Then short runs of a reachability and an invariance query, judged by the general
// monitor and by the dedicated one of a single operator (OperatorMonitor).
//
// Prints events per second (best of --repeat runs) and the peak number of runs the monitor
// holds (its memory beyond the formula's fixed size), with each pattern's ratios of 100x to
// 1x: time and memory should stay flat as bounds grow.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "monitors/monitors.h"

namespace {

using smcbip::monitors::OnlineMonitor;
using smcbip::monitors::Verdict;

/// One event: the values of p and q (r is true throughout).
struct Event {
  bool p = false, q = false;
};

class EventView final : public smcbip::monitors::StateView {
 public:
  double value(const smcbip::monitors::Expr& name) const override {
    const char c = name.path[0];
    return c == 'p' ? event->p : c == 'q' ? event->q : 1.0;
  }
  bool fired(const smcbip::monitors::Expr&) const override { return false; }
  const Event* event = nullptr;
};

/// A pattern over the window [a, b]: its formula and a trace that satisfies it everywhere.
struct Pattern {
  const char* name;
  std::string (*formula)(std::int64_t a, std::int64_t b);
  std::vector<Event> (*trace)(std::size_t n, std::int64_t a, std::int64_t b, std::mt19937& r);
};

bool chance(std::mt19937& random, std::int64_t one_in) {
  return std::uniform_int_distribution<std::int64_t>(
             0, std::max<std::int64_t>(one_in, 1) - 1)(random) == 0;
}

/// Whether some q lies at a time of [t - b, t - a] (`qs` holds the recent q times).
bool after_q(const std::deque<std::int64_t>& qs, std::int64_t t, std::int64_t a, std::int64_t b) {
  for (std::int64_t x : qs) {
    if (x >= t - b && x <= t - a) return true;
  }
  return false;
}

void forget_before(std::deque<std::int64_t>& qs, std::int64_t t) {
  while (!qs.empty() && qs.front() < t) qs.pop_front();
}

/// Traces for the scoped patterns: within [a, b] after each q, p is `p_after_q`; elsewhere
/// it is random.
std::vector<Event> scoped_trace(std::size_t n, std::int64_t a, std::int64_t b, std::mt19937& random,
                                bool p_after_q) {
  std::vector<Event> events(n);
  std::deque<std::int64_t> qs;
  for (std::int64_t t = 0; t < static_cast<std::int64_t>(n); ++t) {
    forget_before(qs, t - b);
    Event& e = events[static_cast<std::size_t>(t)];
    e.q = chance(random, 2 * b);
    if (e.q) qs.push_back(t);
    e.p = after_q(qs, t, a, b) ? p_after_q : chance(random, 2);
  }
  return events;
}

// Absence: after q, no p within [a, b].
std::vector<Event> absence_trace(std::size_t n, std::int64_t a, std::int64_t b,
                                 std::mt19937& random) {
  return scoped_trace(n, a, b, random, false);
}

// Universality: after q, p throughout [a, b].
std::vector<Event> universality_trace(std::size_t n, std::int64_t a, std::int64_t b,
                                      std::mt19937& random) {
  return scoped_trace(n, a, b, random, true);
}

// Recurrence: p within [a, b] from every point: gaps between p's of at most b - a + 1.
std::vector<Event> recurrence_trace(std::size_t n, std::int64_t a, std::int64_t b,
                                    std::mt19937& random) {
  std::vector<Event> events(n);
  std::int64_t last_p = 0;
  for (std::int64_t t = 0; t < static_cast<std::int64_t>(n); ++t) {
    Event& e = events[static_cast<std::size_t>(t)];
    e.p = t == 0 || t - last_p >= b - a + 1 || chance(random, (b - a + 1) / 2);
    if (e.p) last_p = t;
    e.q = chance(random, 2);
  }
  return events;
}

// Response: every q answered by a p within [a, b].
std::vector<Event> response_trace(std::size_t n, std::int64_t a, std::int64_t b,
                                  std::mt19937& random) {
  std::vector<Event> events(n);
  std::deque<std::int64_t> waiting;  // q times not answered yet
  for (std::int64_t t = 0; t < static_cast<std::int64_t>(n); ++t) {
    Event& e = events[static_cast<std::size_t>(t)];
    e.q = chance(random, b);
    if (e.q) waiting.push_back(t);
    const bool due = !waiting.empty() && waiting.front() + b == t;
    e.p = due || chance(random, 2 * (b - a + 1));
    // A p answers every waiting q whose window has opened.
    while (e.p && !waiting.empty() && waiting.front() + a <= t) waiting.pop_front();
  }
  return events;
}

std::vector<Event> random_trace(std::size_t n, std::int64_t, std::int64_t, std::mt19937& random) {
  std::vector<Event> events(n);
  for (Event& e : events) {
    e.p = !chance(random, 50);
    e.q = chance(random, 3);
  }
  return events;
}

std::string range(std::int64_t a, std::int64_t b) {
  return "[" + std::to_string(a) + "," + std::to_string(b) + "]";
}

const Pattern kPatterns[] = {
    {"absence", [](std::int64_t a, std::int64_t b) { return "G (q -> G" + range(a, b) + " !p)"; },
     absence_trace},
    {"universality",
     [](std::int64_t a, std::int64_t b) { return "G (q -> G" + range(a, b) + " p)"; },
     universality_trace},
    {"recurrence", [](std::int64_t a, std::int64_t b) { return "G F" + range(a, b) + " p"; },
     recurrence_trace},
    {"response", [](std::int64_t a, std::int64_t b) { return "G (q -> F" + range(a, b) + " p)"; },
     response_trace},
};

struct Measure {
  double events_per_second = 0;
  std::size_t peak_runs = 0;
};

Measure measure(const std::string& text, const std::vector<Event>& events, int repeat) {
  const smcbip::monitors::ParsedProperties parsed =
      smcbip::monitors::parse_properties("P=? [ " + text + " ]", "bench.mtl");
  if (!parsed.ok()) throw std::runtime_error(parsed.diagnostics.format(parsed.sources));
  const OnlineMonitor blank(*parsed.file.queries.at(0).formula, {1.0, 1.0}, {});
  Measure m;
  double best = 1e300;
  for (int k = 0; k < repeat; ++k) {
    OnlineMonitor monitor = blank;
    EventView view;
    std::size_t peak = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t t = 0; t < events.size(); ++t) {
      view.event = &events[t];
      if (monitor.step(view, static_cast<std::int64_t>(t)) != Verdict::Undecided) {
        throw std::runtime_error(text + ": decided at event " + std::to_string(t));
      }
      if ((t & 1023) == 0) peak = std::max(peak, monitor.held_runs());
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, seconds);
    m.peak_runs = std::max(m.peak_runs, peak);
  }
  m.events_per_second = static_cast<double>(events.size()) / best;
  return m;
}

/// Short runs as statistical checks make them: the events cut into runs of 100, each judged
/// from a reset monitor until it decides. Returns the events read per second (best of
/// `repeat`).
template <class Monitor>
double short_runs(Monitor& monitor, const std::vector<Event>& events, int repeat) {
  double best = 1e300;
  std::size_t read = 0;
  for (int k = 0; k < repeat; ++k) {
    EventView view;
    read = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t run = 0; run + 100 <= events.size(); run += 100) {
      monitor.reset();
      for (std::size_t t = 0; t < 100; ++t) {
        view.event = &events[run + t];
        ++read;
        if (monitor.step(view, static_cast<std::int64_t>(t)) != Verdict::Undecided) break;
      }
      monitor.end(smcbip::monitors::RunEnd::Cut);
    }
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                              .count());
  }
  return static_cast<double>(read) / best;
}

void row(const std::string& name, const std::string& formula, const Measure& m) {
  std::cout << "  " << name;
  for (std::size_t i = name.size(); i < 16; ++i) std::cout << ' ';
  std::cout << formula;
  for (std::size_t i = formula.size(); i < 34; ++i) std::cout << ' ';
  std::cout << static_cast<std::int64_t>(m.events_per_second / 1e3) / 1e3 << " M events/s, peak "
            << m.peak_runs << " runs (" << m.peak_runs * sizeof(smcbip::monitors::online::Run)
            << " bytes)\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"monitor_events: the online monitor's events per second and memory"};
  std::size_t events = 1000000;
  int repeat = 3;
  std::int64_t low = 10, high = 30;
  app.add_option("--events", events, "events per trace")->capture_default_str();
  app.add_option("--repeat", repeat, "runs per case (the best is shown)")->capture_default_str();
  app.add_option("--low", low, "the window's start at 1x")->capture_default_str();
  app.add_option("--high", high, "the window's end at 1x")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::cout << "monitor_events: " << events << " events per trace, best of " << repeat
              << " runs\n";
    for (const Pattern& pattern : kPatterns) {
      Measure first;
      for (std::int64_t scale : {1, 10, 100}) {
        std::mt19937 random(static_cast<std::uint32_t>(scale));
        const std::int64_t a = low * scale, b = high * scale;
        const std::string formula = pattern.formula(a, b);
        const Measure m = measure(formula, pattern.trace(events, a, b, random), repeat);
        row(std::string(pattern.name) + " " + std::to_string(scale) + "x", formula, m);
        if (scale == 1) first = m;
        if (scale == 100) {
          std::cout << "  " << pattern.name << ": 100x against 1x: time ratio "
                    << first.events_per_second / m.events_per_second << ", peak runs "
                    << first.peak_runs << " -> " << m.peak_runs << "\n";
        }
      }
    }
    for (std::int64_t n : {1000, 2000, 5000, 10000}) {
      std::mt19937 random(static_cast<std::uint32_t>(n));
      // U binds loosest: the until in parentheses, or r would be its hold.
      const std::string formula = "G (r || (p U" + range(n, n) + " q))";
      row("until " + std::to_string(n), formula,
          measure(formula, random_trace(events, n, n, random), repeat));
    }
    // The dedicated monitor of one operator over state formulas against the general one.
    for (const char* formula : {"F[0,60] (p && q)", "G[0,80] (p || q)"}) {
      std::mt19937 random(17);
      const std::vector<Event> trace = random_trace(events, 0, 0, random);
      const smcbip::monitors::ParsedProperties parsed =
          smcbip::monitors::parse_properties(std::string("P=? [ ") + formula + " ]", "b.mtl");
      const smcbip::monitors::Formula& f = *parsed.file.queries.at(0).formula;
      OnlineMonitor general(f, {1.0, 1.0}, {});
      smcbip::monitors::OperatorMonitor fast(f, {1.0, 1.0}, {});
      std::cout << "  short runs      " << formula << ": general "
                << short_runs(general, trace, repeat) / 1e6 << " M events/s, dedicated "
                << short_runs(fast, trace, repeat) / 1e6 << " M events/s\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "monitor_events: error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
