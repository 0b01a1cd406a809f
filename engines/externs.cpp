// The registry of extern functions and extern-port classes, and the C builtins models use.
#include "engines/api/externs.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <thread>

#include "engines/stochastic/random_stream.h"

namespace smcbip::engines {

namespace {

bool matches(ValueKind param, ValueKind arg) {
  return param == arg || (param == ValueKind::Float && arg == ValueKind::Int);
}

/// The index of the letter of the printf conversion whose `%` is at `percent` (past its flags,
/// width, precision and length modifiers); format.size() when the format ends before it.
std::size_t conversion_letter(const std::string& format, std::size_t percent) {
  std::size_t end = percent + 1;
  while (end < format.size() &&
         std::string_view("-+ #0123456789.hlLqjzt").find(format[end]) != std::string_view::npos) {
    ++end;
  }
  return end;
}

/// Whether `conversion` prints a value. `%n` would write through the value as a pointer, `%*d`
/// read a width that was never passed, and what C does not define is worse.
bool prints_value(char conversion) {
  return std::string_view("diouxXcsfeEgGaA").find(conversion) != std::string_view::npos;
}

/// One value printed by a conversion: `spec` is what precedes its letter (`%` and flags, width,
/// precision; the written length modifiers, if any, are dropped since the value's kind chooses).
std::string format_value(CallContext& context, std::string spec, char conversion, Val arg,
                         ValueKind kind) {
  std::erase_if(
      spec, [](char c) { return std::string_view("hlLqjzt").find(c) != std::string_view::npos; });
  char buffer[512];
  const std::string_view floats = "feEgGaA";
  if (floats.find(conversion) != std::string_view::npos) {
    const double value = kind == ValueKind::Float ? arg.f : static_cast<double>(arg.i);
    std::snprintf(buffer, sizeof buffer, (spec + conversion).c_str(), value);
  } else if (conversion == 's') {
    const std::string text = kind == ValueKind::String ? context.strings.text(arg.s)
                             : kind == ValueKind::Bool ? (arg.b ? "true" : "false")
                                                       : std::to_string(arg.i);
    std::snprintf(buffer, sizeof buffer, (spec + 's').c_str(), text.c_str());
  } else if (conversion == 'c') {
    std::snprintf(buffer, sizeof buffer, (spec + 'c').c_str(), static_cast<int>(arg.i));
  } else {
    const long long value = kind == ValueKind::Float  ? static_cast<long long>(arg.f)
                            : kind == ValueKind::Bool ? (arg.b ? 1 : 0)
                                                      : static_cast<long long>(arg.i);
    std::snprintf(buffer, sizeof buffer, (spec + "ll" + conversion).c_str(), value);
  }
  return buffer;
}

/// printf with BIP values: ints print through `ll` conversions, floats as double, strings as
/// text. A conversion without a matching argument, or one that prints no value (`%n`, `%*d`, a
/// letter C does not define), prints as written.
std::string format_printf(CallContext& context, std::span<const Val> args) {
  const std::string& format = context.strings.text(args[0].s);
  std::string out;
  std::size_t next = 1;
  for (std::size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%') {
      out += format[i];
      continue;
    }
    const std::size_t end = conversion_letter(format, i);
    if (end >= format.size()) {
      out += format.substr(i);
      break;
    }
    const char conversion = format[end];
    if (conversion == '%') {
      out += '%';
    } else if (!prints_value(conversion) || next >= args.size()) {
      out += format.substr(i, end - i + 1);
    } else {
      const ValueKind kind =
          next < context.arg_kinds.size() ? context.arg_kinds[next] : ValueKind::Int;
      out += format_value(context, format.substr(i, end - i), conversion, args[next], kind);
      ++next;
    }
    i = end;
  }
  return out;
}

}  // namespace

void Externs::add_raw(std::string name, std::vector<ValueKind> params, ValueKind result,
                      ExternFn fn) {
  functions_.push_back({std::move(name), std::move(params), result, std::move(fn), false, false});
}

void Externs::add_variadic(std::string name, std::vector<ValueKind> params, ValueKind result,
                           ExternFn fn) {
  functions_.push_back({std::move(name), std::move(params), result, std::move(fn), true, false});
}

void Externs::declare_pure(const std::string& name) {
  for (Function& f : functions_) {
    if (f.name == name) f.pure = true;
  }
}

void Externs::add_port_class(std::string class_name, ExternPortFactory factory) {
  port_classes_.emplace_back(std::move(class_name), std::move(factory));
}

const Externs::Function* Externs::find(const std::string& name,
                                       const std::vector<ValueKind>& params) const {
  const Function* loose = nullptr;
  // Later registrations win, so a host can override a builtin.
  for (auto it = functions_.rbegin(); it != functions_.rend(); ++it) {
    const Function& f = *it;
    if (f.name != name) continue;
    if (f.variadic ? params.size() < f.params.size() : params.size() != f.params.size()) {
      continue;
    }
    bool exact = true, ok = true;
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      exact = exact && f.params[i] == params[i];
      ok = ok && matches(f.params[i], params[i]);
    }
    if (exact) return &f;
    if (ok && !loose) loose = &f;
  }
  return loose;
}

const ExternPortFactory* Externs::find_port_class(const std::string& class_name) const {
  for (auto it = port_classes_.rbegin(); it != port_classes_.rend(); ++it) {
    if (it->first == class_name) return &it->second;
  }
  return nullptr;
}

Externs Externs::with_builtins() {
  Externs externs;
  externs.add_variadic("printf", {ValueKind::String}, ValueKind::Int,
                       [](CallContext& context, std::span<const Val> args) {
                         const std::string text = format_printf(context, args);
                         context.out << text;
                         return make_int(static_cast<std::int64_t>(text.size()));
                       });
  externs.add("sleep", [](std::int64_t seconds) {
    std::this_thread::sleep_for(std::chrono::seconds(seconds));
    return std::int64_t{0};
  });
  externs.add("usleep", [](std::int64_t microseconds) {
    std::this_thread::sleep_for(std::chrono::microseconds(microseconds));
    return std::int64_t{0};
  });
  externs.add("min", [](std::int64_t a, std::int64_t b) { return std::min(a, b); });
  externs.add("max", [](std::int64_t a, std::int64_t b) { return std::max(a, b); });
  externs.add("min", [](double a, double b) { return std::min(a, b); });
  externs.add("max", [](double a, double b) { return std::max(a, b); });
  externs.add("abs", [](std::int64_t a) { return a < 0 ? -a : a; });
  for (const char* name : {"min", "max", "abs"}) externs.declare_pure(name);
  externs.add("rand", [](CallContext& context) -> std::int64_t {
    // RAND_MAX bounds the values as C's rand does; the run's stream keeps them reproducible.
    if (context.random == nullptr) return 0;
    return static_cast<std::int64_t>(context.random->below(std::uint64_t{RAND_MAX} + 1));
  });
  return externs;
}

}  // namespace smcbip::engines
