// Extern C++ functions and extern-port event sources that interpreted models call, registered
// from C++ by the host program (builtins such as printf, min, sleep come ready-made).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "bipc/ir/ir.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"

namespace smcbip::engines {

using bipc::ir::ValueKind;

class RandomStream;

/// What an extern function throws when it cannot go on: the run ends in a model error located
/// at the call, with this message (the engines catch nothing else an extern function throws).
struct ExternFault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// What an extern function sees of the run that calls it: the model's output stream (the trace
/// stream, so prints interleave with engine lines), the string pool of the model, and the run's
/// random stream (builtin rand() draws from it, so runs stay reproducible).
struct CallContext {
  std::ostream& out;
  StringPool& strings;
  RandomStream* random = nullptr;
  std::span<const ValueKind> arg_kinds = {};  // kinds of this call's arguments (variadic calls)
};

using ExternFn = std::function<Val(CallContext&, std::span<const Val>)>;

/// One extern event for an extern port: when it happens and the values of the port-type
/// parameters it carries.
struct ExternEvent {
  TimeValue time = 0;
  std::vector<Val> values;
};

/// The events of one extern port, pulled by the engine in time order. Sources of one class may
/// share state (e.g. a common clock) through their factory.
class ExternPortSource {
 public:
  virtual ~ExternPortSource() = default;
  /// The next event; `now` is the engine's current time. nullopt: no more events, ever.
  virtual std::optional<ExternEvent> next(TimeValue now) = 0;
  /// As next(), into `event`, whose buffer the engine reuses: false for no more events. A
  /// source that must not allocate per event overrides it.
  virtual bool pull(TimeValue now, ExternEvent& event) {
    std::optional<ExternEvent> next_event = next(now);
    if (!next_event) return false;
    event = std::move(*next_event);
    return true;
  }
};

/// Makes the source of one extern port declared `extern port T p(...) as "<class>"`.
using ExternPortFactory = std::function<std::unique_ptr<ExternPortSource>(
    const std::string& atom_path, const std::string& port_name)>;

namespace detail {
template <class T>
constexpr ValueKind kind_of() {
  using U = std::remove_cvref_t<T>;
  if constexpr (std::is_same_v<U, void>)
    return ValueKind::Void;
  else if constexpr (std::is_same_v<U, bool>)
    return ValueKind::Bool;
  else if constexpr (std::is_integral_v<U>)
    return ValueKind::Int;
  else if constexpr (std::is_floating_point_v<U>)
    return ValueKind::Float;
  else if constexpr (std::is_same_v<U, std::string>)
    return ValueKind::String;
  else
    static_assert(sizeof(U) == 0, "extern parameters are bool, integers, floats or strings");
}
template <class T>
T from_val(const CallContext& context, Val v) {
  using U = std::remove_cvref_t<T>;
  if constexpr (std::is_same_v<U, bool>)
    return v.b;
  else if constexpr (std::is_integral_v<U>)
    return static_cast<U>(v.i);
  else if constexpr (std::is_floating_point_v<U>)
    return static_cast<U>(v.f);
  else
    return context.strings.text(v.s);
}
template <class T>
Val to_val(CallContext& context, T&& value) {
  using U = std::remove_cvref_t<T>;
  if constexpr (std::is_same_v<U, bool>)
    return make_bool(value);
  else if constexpr (std::is_integral_v<U>)
    return make_int(static_cast<std::int64_t>(value));
  else if constexpr (std::is_floating_point_v<U>)
    return make_float(static_cast<double>(value));
  else {
    Val x;
    x.s = context.strings.intern(value);
    return x;
  }
}
}  // namespace detail

/// The extern functions and extern-port classes a model may use. Functions are looked up by
/// name and parameter kinds (BIP allows overloads); an int argument also matches a float
/// parameter as the checker allows.
class Externs {
 public:
  /// printf, sleep, usleep, min, max, abs, rand (seeded per run), as C declares them.
  static Externs with_builtins();

  void add_raw(std::string name, std::vector<ValueKind> params, ValueKind result, ExternFn fn);
  /// A C-style variadic function: `params` are the fixed leading ones; any arguments may follow.
  void add_variadic(std::string name, std::vector<ValueKind> params, ValueKind result, ExternFn fn);

  /// Registers a C++ callable; its parameters and result map to BIP kinds (bool, integers,
  /// floats, std::string). An optional first parameter `CallContext&` gives access to the output.
  template <class R, class... A>
  void add(std::string name, std::function<R(CallContext&, A...)> fn) {
    add_raw(std::move(name), {detail::kind_of<A>()...}, detail::kind_of<R>(),
            [fn](CallContext& c, std::span<const Val> args) -> Val {
              return invoke(c, fn, args, std::index_sequence_for<A...>{});
            });
  }
  template <class R, class... A>
  void add(std::string name, std::function<R(A...)> fn) {
    add<R, A...>(std::move(name), std::function<R(CallContext&, A...)>([fn](CallContext&, A... a) {
                   return fn(std::forward<A>(a)...);
                 }));
  }
  template <class F>
  void add(std::string name, F fn) {
    add(std::move(name), std::function(fn));
  }

  /// Declares every function registered so far under `name` pure: its result depends on its
  /// arguments only, it has no side effect (no output, no use of the CallContext's stream or
  /// random numbers) and it may run on several threads at once. The multithread scheduler fires
  /// atoms in parallel only when their code calls pure functions alone.
  void declare_pure(const std::string& name);

  void add_port_class(std::string class_name, ExternPortFactory factory);

  struct Function {
    std::string name;
    std::vector<ValueKind> params;
    ValueKind result = ValueKind::Void;
    ExternFn fn;
    bool variadic = false;
    bool pure = false;  // see declare_pure
  };
  /// The function for a call with these argument kinds, or nullptr.
  const Function* find(const std::string& name, const std::vector<ValueKind>& params) const;
  const ExternPortFactory* find_port_class(const std::string& class_name) const;

 private:
  template <class R, class... A, std::size_t... I>
  static Val invoke(CallContext& c, const std::function<R(CallContext&, A...)>& fn,
                    std::span<const Val> args, std::index_sequence<I...>) {
    if constexpr (std::is_void_v<R>) {
      fn(c, detail::from_val<A>(c, args[I])...);
      return make_int(0);
    } else {
      return detail::to_val(c, fn(c, detail::from_val<A>(c, args[I])...));
    }
  }

  std::vector<Function> functions_;
  std::vector<std::pair<std::string, ExternPortFactory>> port_classes_;
};

}  // namespace smcbip::engines
