// Projected observable traces of an untimed system, breadth first with silent steps closed.
#include "tests/taste2bip/watchdog_traces.h"

#include <algorithm>
#include <deque>
#include <memory>
#include <sstream>
#include <unordered_set>
#include <utility>

#include "engines/api/model.h"
#include "engines/explore.h"
#include "engines/semantics/runtime.h"

namespace smcbip::taste2bip::test {

namespace {

using engines::RunState;

/// The states reached after one trace, each once.
struct Bucket {
  std::vector<RunState> states;
  std::unordered_set<std::string> keys;
  void add(RunState state) {
    if (keys.insert(engines::state_key(state)).second) states.push_back(std::move(state));
  }
};

/// A runtime over the system with what it refers to, and the observation as indices.
class TraceExplorer {
 public:
  TraceExplorer(const bipc::ir::System& system, const engines::Externs& externs,
                const WatchdogObservation& observation, const TraceBounds& bounds)
      : system_(system), model_(system), random_(1, 0), bounds_(bounds) {
    out_.problem = engines::build_layout(system, layout_);
    if (out_.problem.empty()) {
      out_.problem = engines::bind_functions(system, externs, strings_, functions_);
    }
    if (!out_.problem.empty()) return;
    runtime_ = std::make_unique<engines::Runtime>(model_, layout_, functions_, strings_, text_,
                                                  random_, engines::RuntimeOptions{});
    index_observation(observation);
  }

  TraceSet run() {
    if (!out_.problem.empty()) return std::move(out_);
    if (!runtime_->initialize() || !runtime_->resume_atoms(0)) {
      out_.problem = "initialisation failed: " + runtime_->error().message;
      return std::move(out_);
    }
    std::map<Trace, Bucket> level;
    RunState initial = runtime_->state();
    erase(initial);
    level[{}].add(std::move(initial));
    out_.traces.insert(Trace{});
    for (std::size_t depth = 0; depth < bounds_.events && !level.empty(); ++depth) {
      std::map<Trace, Bucket> next;
      for (auto& [trace, bucket] : level) close_and_extend(trace, bucket, next);
      level = std::move(next);
    }
    return std::move(out_);
  }

 private:
  void index_observation(const WatchdogObservation& observation) {
    for (bipc::ir::Index a = 0; a < system_.atoms.size(); ++a) {
      const bipc::ir::AtomType& type = system_.atom_types[system_.atoms[a].type];
      const std::string& path = system_.atoms[a].path;
      for (bipc::ir::Index p = 0; p < type.ports.size(); ++p) {
        const auto it = observation.ports.find(path + "." + type.ports[p].name);
        if (it != observation.ports.end()) port_labels_[{a, p}] = it->second;
      }
      for (bipc::ir::Index d = 0; d < type.data.size(); ++d) {
        const std::string& name = type.data[d].name;
        if (observation.erased_data.contains(path + "." + name) ||
            observation.erased_data.contains("*." + name)) {
          erased_slots_.push_back(layout_.atom_data[a] + d);
        }
      }
      // taste2bip's SDL atoms keep their state marked during a transition and take the token
      // of `ready`: the state is entered when the token comes back.
      std::size_t ready = kNoPlace;
      for (bipc::ir::Index p = 0; p < type.places.size(); ++p) {
        if (type.places[p] == "ready") ready = layout_.atom_places[a] + p;
      }
      for (bipc::ir::Index p = 0; p < type.places.size(); ++p) {
        const auto it = observation.places.find(path + "." + type.places[p]);
        if (it != observation.places.end()) {
          place_labels_.push_back({layout_.atom_places[a] + p, ready, it->second});
        }
      }
    }
  }

  void erase(RunState& state) const {
    for (const std::size_t slot : erased_slots_) state.data[slot] = engines::make_int(0);
  }

  /// The labels a step shows: its observed ports (sorted), then the places it entered (sorted).
  Trace labels(const std::vector<std::pair<bipc::ir::Index, bipc::ir::Index>>& ports,
               const RunState& before, const RunState& after) const {
    Trace shown, entered;
    for (const auto& atom_port : ports) {
      const auto it = port_labels_.find(atom_port);
      if (it != port_labels_.end()) shown.push_back(it->second);
    }
    for (const PlaceLabel& l : place_labels_) {
      const bool back = l.ready != kNoPlace && after.marking[l.ready] && !before.marking[l.ready];
      if (after.marking[l.place] && (!before.marking[l.place] || back)) entered.push_back(l.label);
    }
    std::sort(shown.begin(), shown.end());
    std::sort(entered.begin(), entered.end());
    shown.insert(shown.end(), entered.begin(), entered.end());
    return shown;
  }

  /// Explores the silent closure of `trace`'s states; observable steps go to `next`.
  void close_and_extend(const Trace& trace, Bucket& bucket, std::map<Trace, Bucket>& next) {
    std::deque<std::pair<RunState, std::size_t>> queue;  // with its silent depth
    for (RunState& s : bucket.states) queue.emplace_back(std::move(s), 0);
    while (!queue.empty()) {
      if (out_.states >= bounds_.states) {
        out_.cut = true;
        return;
      }
      auto [state, silent] = std::move(queue.front());
      queue.pop_front();
      ++out_.states;
      if (!runtime_->restore(state) || !runtime_->compute_items()) {
        ++out_.errors;
        continue;
      }
      const std::vector<engines::Item> items = runtime_->items();
      for (const engines::Item& item : items) {
        std::vector<std::pair<bipc::ir::Index, bipc::ir::Index>> ports;
        if (!runtime_->restore(state) || !runtime_->compute_items()) continue;
        runtime_->append_atom_ports(item, ports);
        if (!runtime_->execute(item, state.now) || !runtime_->resume_atoms(state.now)) {
          ++out_.errors;
          continue;
        }
        RunState after = runtime_->state();
        after.now = state.now;
        erase(after);
        const Trace shown = labels(ports, state, after);
        if (shown.empty()) {
          std::string key = engines::state_key(after);
          if (bucket.keys.contains(key)) continue;
          if (silent + 1 > bounds_.silent_steps) {
            out_.cut = true;  // a new state beyond the bound: left unexplored
            continue;
          }
          bucket.keys.insert(std::move(key));
          queue.emplace_back(std::move(after), silent + 1);
          continue;
        }
        Trace extended = trace;
        for (const std::string& label : shown) {
          if (extended.size() == bounds_.events) break;
          extended.push_back(label);
          out_.traces.insert(extended);
        }
        if (extended.size() < bounds_.events) next[extended].add(std::move(after));
      }
    }
  }

  const bipc::ir::System& system_;
  engines::InterpretedModel model_;
  engines::Layout layout_;
  engines::StringPool strings_;
  engines::BoundFunctions functions_;
  std::ostringstream text_;  // the model's own output, not shown
  engines::RandomStream random_;
  TraceBounds bounds_;
  std::unique_ptr<engines::Runtime> runtime_;
  std::map<std::pair<bipc::ir::Index, bipc::ir::Index>, std::string> port_labels_;
  static constexpr std::size_t kNoPlace = static_cast<std::size_t>(-1);
  struct PlaceLabel {
    std::size_t place = 0, ready = kNoPlace;  // in RunState::marking
    std::string label;
  };
  std::vector<PlaceLabel> place_labels_;
  std::vector<std::size_t> erased_slots_;  // in RunState::data
  TraceSet out_;
};

/// The first trace of `a` missing from `b`.
std::optional<Trace> first_missing(const TraceSet& a, const TraceSet& b) {
  for (const Trace& t : a.traces) {
    if (!b.traces.contains(t)) return t;
  }
  return std::nullopt;
}

/// What `other` does after the longest prefix of `trace` it has.
std::string continuations(const Trace& trace, const TraceSet& other) {
  Trace prefix = trace;
  while (!prefix.empty() && !other.traces.contains(prefix)) prefix.pop_back();
  std::ostringstream out;
  out << "after [" << trace_text(prefix) << "] it continues with:";
  bool any = false;
  for (const Trace& t : other.traces) {
    if (t.size() != prefix.size() + 1 || !std::equal(prefix.begin(), prefix.end(), t.begin())) {
      continue;
    }
    out << " " << t.back() << ";";
    any = true;
  }
  if (!any) out << " nothing (its traces end there)";
  return out.str();
}

}  // namespace

TraceSet projected_traces(const bipc::ir::System& untimed, const engines::Externs& externs,
                          const WatchdogObservation& observation, const TraceBounds& bounds) {
  TraceExplorer explorer(untimed, externs, observation, bounds);
  return explorer.run();
}

TraceDifference compare_traces(const TraceSet& left, const TraceSet& right) {
  return {first_missing(left, right), first_missing(right, left)};
}

std::string trace_text(const Trace& trace) {
  if (trace.empty()) return "<empty>";
  std::string text;
  for (const std::string& event : trace) text += (text.empty() ? "" : ", ") + event;
  return text;
}

std::string difference_report(const TraceSet& left, const TraceSet& right,
                              const TraceDifference& difference, const std::string& left_name,
                              const std::string& right_name) {
  std::ostringstream out;
  if (difference.only_left) {
    out << left_name << " has the trace [" << trace_text(*difference.only_left) << "] that "
        << right_name << " has not; " << right_name << " "
        << continuations(*difference.only_left, right) << "\n";
  }
  if (difference.only_right) {
    out << right_name << " has the trace [" << trace_text(*difference.only_right) << "] that "
        << left_name << " has not; " << left_name << " "
        << continuations(*difference.only_right, left) << "\n";
  }
  if (difference.equal()) out << left_name << " and " << right_name << " have the same traces\n";
  return out.str();
}

}  // namespace smcbip::taste2bip::test
