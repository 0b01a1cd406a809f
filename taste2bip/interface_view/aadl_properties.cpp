// Values of the AADL property associations the interface view keeps.
#include "taste2bip/interface_view/detail/aadl_properties.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace smcbip::taste2bip::detail {
namespace {

/// AADL_Project's Time_Units, in milliseconds.
std::optional<double> unit_in_ms(const std::string& unit) {
  const std::string key = aadl_key(unit);
  if (key == "ps") return 1e-9;
  if (key == "ns") return 1e-6;
  if (key == "us") return 1e-3;
  if (key == "ms") return 1.0;
  if (key == "sec") return 1e3;
  if (key == "min") return 60e3;
  if (key == "hr") return 3600e3;
  return std::nullopt;
}

std::string without_underscores(const std::string& number) {
  std::string digits;
  for (char c : number) {
    if (c != '_') digits += c;
  }
  return digits;
}

}  // namespace

void AadlPropertyValues::expected(const AadlProperty& p, std::size_t pos, const std::string& what) {
  if (pos >= p.value.size()) {
    const AadlToken& last = p.value.back();
    errors_.error(last.at, "expected " + what + " after '" + last.text + "' in " + p.name);
    return;
  }
  const AadlToken& t = p.value[pos];
  const std::string got = t.kind == AadlTokenKind::String ? "\"" + t.text + "\"" : t.text;
  errors_.error(t.at, "expected " + what + " in " + p.name + ", got '" + got + "'");
}

std::optional<std::string> AadlPropertyValues::string(const AadlProperty& p) {
  if (p.value.size() != 1 || p.value[0].kind != AadlTokenKind::String) {
    expected(p, p.value[0].kind == AadlTokenKind::String ? 1 : 0, "a string");
    return std::nullopt;
  }
  return p.value[0].text;
}

std::string AadlPropertyValues::first_name(const AadlProperty& p) {
  for (const AadlToken& t : p.value) {
    if (t.kind == AadlTokenKind::Identifier || t.kind == AadlTokenKind::String) return t.text;
  }
  expected(p, 0, "a name");
  return "";
}

std::optional<InterfaceKind> AadlPropertyValues::kind(const AadlProperty& p) {
  const std::string key = aadl_key(p.value[0].text);
  std::optional<InterfaceKind> kind;
  if (p.value[0].kind == AadlTokenKind::Identifier) {
    if (key == "cyclic") kind = InterfaceKind::Cyclic;
    if (key == "sporadic") kind = InterfaceKind::Sporadic;
    if (key == "protected") kind = InterfaceKind::Protected;
    if (key == "unprotected") kind = InterfaceKind::Unprotected;
    if (key == "any") kind = InterfaceKind::Any;
  }
  if (!kind || p.value.size() != 1) {
    expected(p, kind ? 1 : 0, kind ? "';'" : "cyclic, sporadic, protected, unprotected or any");
    return std::nullopt;
  }
  return kind;
}

std::optional<std::uint32_t> AadlPropertyValues::count(const AadlProperty& p) {
  const AadlToken& t = p.value[0];
  std::uint32_t value = 0;
  const std::string digits = without_underscores(t.text);
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (t.kind != AadlTokenKind::Number || ec != std::errc() ||
      end != digits.data() + digits.size()) {
    expected(p, 0, "a non-negative integer below 2^32");
    return std::nullopt;
  }
  if (p.value.size() != 1) {
    expected(p, 1, "';'");
    return std::nullopt;
  }
  return value;
}

std::optional<Milliseconds> AadlPropertyValues::time_at(const AadlProperty& p, std::size_t& pos) {
  bool negative = false;
  if (pos < p.value.size() && p.value[pos].kind == AadlTokenKind::Minus) {
    negative = true;
    ++pos;
  }
  if (pos >= p.value.size() || p.value[pos].kind != AadlTokenKind::Number) {
    expected(p, pos, "a time (a number and a unit, like 100 ms)");
    return std::nullopt;
  }
  const double number = std::strtod(without_underscores(p.value[pos].text).c_str(), nullptr);
  ++pos;
  const std::optional<double> unit =
      pos < p.value.size() && p.value[pos].kind == AadlTokenKind::Identifier
          ? unit_in_ms(p.value[pos].text)
          : std::nullopt;
  if (!unit) {
    expected(p, pos, "a time unit (ps, ns, us, ms, sec, min or hr)");
    return std::nullopt;
  }
  ++pos;
  const double ms = (negative ? -number : number) * *unit;
  if (!std::isfinite(ms)) {
    expected(p, pos - 2, "a finite time");
    return std::nullopt;
  }
  return ms;
}

std::optional<Milliseconds> AadlPropertyValues::time(const AadlProperty& p) {
  std::size_t pos = 0;
  const auto value = time_at(p, pos);
  if (value && pos != p.value.size()) {
    expected(p, pos, "';'");
    return std::nullopt;
  }
  return value;
}

std::optional<std::pair<Milliseconds, Milliseconds>> AadlPropertyValues::time_range(
    const AadlProperty& p) {
  std::size_t pos = 0;
  const auto low = time_at(p, pos);
  if (!low) return std::nullopt;
  if (pos >= p.value.size() || p.value[pos].kind != AadlTokenKind::DotDot) {
    expected(p, pos, "'..' and the upper bound");
    return std::nullopt;
  }
  ++pos;
  const auto high = time_at(p, pos);
  if (!high) return std::nullopt;
  if (pos != p.value.size()) {
    expected(p, pos, "';'");
    return std::nullopt;
  }
  return std::make_pair(*low, *high);
}

}  // namespace smcbip::taste2bip::detail
