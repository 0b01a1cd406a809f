// The original watchdog BIP made runnable: its textual adaptation and its extern functions.
#include "tests/taste2bip/watchdog_model.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <mutex>
#include <regex>
#include <vector>

#include "bipc/bipc.h"
#include "tests/engines/temp_model.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip::test {

namespace {

using bipc::ir::ValueKind;
using engines::CallContext;
using engines::Val;

/// Immutable values named by handles: equal values get equal handles; handle 0 is T{}.
template <class T>
class ValuePool {
 public:
  ValuePool() { handle(T{}); }
  std::int64_t handle(const T& value) {
    const std::lock_guard lock(mutex_);
    auto [it, fresh] = ids_.try_emplace(value, static_cast<std::int64_t>(values_.size()));
    if (fresh) values_.push_back(value);
    return it->second;
  }
  T value(std::int64_t handle) {
    const std::lock_guard lock(mutex_);
    if (handle < 0 || static_cast<std::size_t>(handle) >= values_.size()) return T{};
    return values_[static_cast<std::size_t>(handle)];
  }

 private:
  std::mutex mutex_;
  std::map<T, std::int64_t> ids_;
  std::vector<T> values_;
};

using Queue = std::vector<std::int64_t>;  // record handles, front first

ValuePool<Motion2D>& records() {
  static ValuePool<Motion2D> pool;
  return pool;
}
ValuePool<double>& angles() {
  static ValuePool<double> pool;
  return pool;
}
ValuePool<Queue>& queues() {
  static ValuePool<Queue> pool;
  return pool;
}

Val handle_val(std::int64_t h) { return engines::make_int(h); }

/// get_<field> and set_<field> of a Motion2D record.
void add_field(engines::Externs& externs, const std::string& name, double Motion2D::*field) {
  externs.add_raw("get_" + name, {ValueKind::Extern}, ValueKind::Float,
                  [field](CallContext&, std::span<const Val> a) {
                    return engines::make_float(records().value(a[0].i).*field);
                  });
  externs.add_raw("set_" + name, {ValueKind::Extern, ValueKind::Float}, ValueKind::Extern,
                  [field](CallContext&, std::span<const Val> a) {
                    Motion2D record = records().value(a[0].i);
                    record.*field = a[1].f;
                    return handle_val(records().handle(record));
                  });
  externs.declare_pure("get_" + name);
  externs.declare_pure("set_" + name);
}

void add_queue(engines::Externs& externs) {
  const ValueKind e = ValueKind::Extern;
  externs.add_raw("get_size", {e}, ValueKind::Int, [](CallContext&, std::span<const Val> a) {
    return engines::make_int(static_cast<std::int64_t>(queues().value(a[0].i).size()));
  });
  externs.add_raw("push_back", {e, e, ValueKind::Int}, e, [](CallContext&, std::span<const Val> a) {
    Queue q = queues().value(a[0].i);
    if (static_cast<std::int64_t>(q.size()) >= a[2].i) return a[0];  // full: dropped
    q.push_back(a[1].i);
    return handle_val(queues().handle(q));
  });
  externs.add_raw("front", {e}, e, [](CallContext&, std::span<const Val> a) {
    const Queue q = queues().value(a[0].i);
    return handle_val(q.empty() ? 0 : q.front());
  });
  externs.add_raw("pop_front", {e}, e, [](CallContext&, std::span<const Val> a) {
    Queue q = queues().value(a[0].i);
    if (!q.empty()) q.erase(q.begin());
    return handle_val(queues().handle(q));
  });
  for (const char* name : {"get_size", "push_back", "front", "pop_front"}) {
    externs.declare_pure(name);
  }
}

void add_output(engines::Externs& externs) {
  for (const ValueKind kind :
       {ValueKind::Bool, ValueKind::Int, ValueKind::Float, ValueKind::String}) {
    for (const bool line : {false, true}) {
      externs.add_raw(line ? "writeln" : "write", {kind}, ValueKind::Void,
                      [kind, line](CallContext& c, std::span<const Val> a) {
                        switch (kind) {
                          case ValueKind::Bool:
                            c.out << (a[0].b ? "true" : "false");
                            break;
                          case ValueKind::Int:
                            c.out << a[0].i;
                            break;
                          case ValueKind::Float:
                            c.out << a[0].f;
                            break;
                          default:
                            c.out << c.strings.text(a[0].s);
                            break;
                        }
                        if (line) c.out << '\n';
                        return engines::make_int(0);
                      });
    }
  }
}

/// Replaces every match of `pattern` by `replacement`; false unless there were `expected`.
bool replace_counted(std::string& text, const std::string& pattern, const std::string& replacement,
                     std::ptrdiff_t expected, std::string& why) {
  const std::regex re(pattern);
  const std::ptrdiff_t found =
      std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator());
  if (found != expected) {
    why = "adaptation `" + pattern + "`: " + std::to_string(found) + " matches, expected " +
          std::to_string(expected);
    return false;
  }
  text = std::regex_replace(text, re, replacement);
  return true;
}

}  // namespace

std::filesystem::path watchdog_original_file() {
  return shared_data_dir() / "esrocos-mc_watchdog" / "BipModel" / "sources" /
         "InterfaceViewFull.bip";
}

std::optional<std::string> watchdog_adapted_text(const std::string& original, std::string& why) {
  std::string text = original;
  const std::string queue = "queueBase_commands_Motion2D", record = "asn1SccBase_commands_Motion2D";
  const bool ok =
      // 1. Setters return the record: declarations, then every call statement.
      replace_counted(text, R"(extern function (set_\w+) ?\((\w+), const float\))",
                      "extern function $2 $1(const $2, const float)", 4, why) &&
      replace_counted(text, R"(\b(set_(?:translation|rotation|heading|rad))\((\w+),)",
                      "$2 = $1($2,", 6, why) &&
      // 2. The FIFO is a value.
      replace_counted(text, R"(extern function push_back\()" + queue + ", " + record + R"(, int\))",
                      "extern function " + queue + " push_back(const " + queue + ", const " +
                          record + ", const int)",
                      1, why) &&
      replace_counted(text, "extern function " + record + R"( pop_front\()" + queue + R"(\))",
                      "extern function " + record + " front(const " + queue +
                          ")\n  extern function " + queue + " pop_front(const " + queue + ")",
                      1, why) &&
      replace_counted(text, R"(\bpush_back\(q, val, size\);)", "q = push_back(q, val, size);", 3,
                      why) &&
      replace_counted(text, R"(r\.v = pop_front\(s\.q\);)",
                      "r.v = front(s.q); s.q = pop_front(s.q);", 1, why);
  if (!ok) return std::nullopt;
  return text;
}

engines::Externs watchdog_externs() {
  engines::Externs externs = engines::Externs::with_builtins();
  add_watchdog_externs(externs);
  return externs;
}

void add_watchdog_externs(engines::Externs& externs) {
  add_field(externs, "translation", &Motion2D::translation);
  add_field(externs, "rotation", &Motion2D::rotation);
  add_field(externs, "heading", &Motion2D::heading);
  externs.add_raw("get_rad", {ValueKind::Extern}, ValueKind::Float,
                  [](CallContext&, std::span<const Val> a) {
                    return engines::make_float(angles().value(a[0].i));
                  });
  externs.add_raw(
      "set_rad", {ValueKind::Extern, ValueKind::Float}, ValueKind::Extern,
      [](CallContext&, std::span<const Val> a) { return handle_val(angles().handle(a[1].f)); });
  add_queue(externs);
  add_output(externs);
}

std::optional<bipc::ir::System> load_bip_text(const std::string& text, const std::string& file_name,
                                              const std::string& root, std::string& why) {
  const tests::TempDir dir;
  const std::filesystem::path file = dir.write(file_name, text);
  bipc::FrontendResult result = bipc::run_frontend({file.string(), {}, root}, true);
  if (!result.system) {
    why = result.diags.format(result.model.files);
    return std::nullopt;
  }
  return std::move(*result.system);
}

std::optional<std::string> watchdog_adapted_original(std::string& why) {
  const std::string original = file_text(watchdog_original_file());
  if (original.empty()) {
    why = "cannot read " + watchdog_original_file().string();
    return std::nullopt;
  }
  return watchdog_adapted_text(original, why);
}

std::optional<bipc::ir::System> load_watchdog_original(std::string& why) {
  const std::optional<std::string> adapted = watchdog_adapted_original(why);
  if (!adapted) return std::nullopt;
  return load_bip_text(*adapted, "InterfaceViewFull.bip", "Syst()", why);
}

void remove_fault_transitions(bipc::ir::System& system) {
  for (bipc::ir::AtomType& type : system.atom_types) {
    std::erase_if(type.transitions, [&](const bipc::ir::Transition& t) {
      if (t.port == bipc::ir::kNone) return false;
      const std::vector<bipc::ir::Annotation>& notes = type.ports[t.port].annotations;
      return std::any_of(notes.begin(), notes.end(),
                         [](const bipc::ir::Annotation& a) { return a.name == "fault"; });
    });
  }
}

WatchdogObservation watchdog_observation(WatchdogNaming naming, bool watchdog_calls,
                                         bool watchdog_wait) {
  struct Call {
    const char *function, *interface, *direction;
  };
  std::vector<Call> calls = {
      {"JoystickDriver", "step", "in"},     {"JoystickDriver", "cmd", "out"},
      {"CmdDispatcher", "cmd", "in"},       {"CmdDispatcher", "log_cmd", "out"},
      {"CmdDispatcher", "test_cmd", "out"}, {"Logger", "log_cmd", "in"},
      {"BLSClient", "mot_cmd", "in"}};
  if (watchdog_calls) {
    calls.push_back({"Watchdog", "test_cmd", "in"});
    calls.push_back({"Watchdog", "mot_cmd", "out"});
  }
  WatchdogObservation o;
  for (const Call& c : calls) {
    const std::string f = c.function, port = std::string(c.interface) + "_" + c.direction;
    o.ports[f + "." + (naming == WatchdogNaming::Original ? f + "_" : "") + port] =
        f + "." + c.interface;
  }
  for (const char* f : {"JoystickDriver", "CmdDispatcher", "Logger", "BLSClient"}) {
    o.places[std::string(f) + ".Wait"] = std::string(f) + ".Wait";
  }
  if (watchdog_wait) o.places["Watchdog.Wait"] = "Watchdog.Wait";
  return o;
}

Motion2D motion2d_value(std::int64_t handle) { return records().value(handle); }

}  // namespace smcbip::taste2bip::test
