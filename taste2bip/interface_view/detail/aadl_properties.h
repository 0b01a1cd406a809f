// Values of the AADL property associations the interface view keeps: strings, names, integers,
// times with units and time ranges, each checked with a located error saying what was expected.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "taste2bip/interface_view/detail/aadl_syntax.h"
#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip::detail {

/// Interprets property values; a value of the wrong form is an error and gives nullopt.
class AadlPropertyValues {
 public:
  explicit AadlPropertyValues(AadlErrors& errors) : errors_(errors) {}

  /// `"text"`.
  std::optional<std::string> string(const AadlProperty& p);
  /// The first name or string of `(SDL)`, `SDL` or `("SDL")`; empty (and an error) when none.
  std::string first_name(const AadlProperty& p);
  /// `cyclic`, `sporadic`, `protected`, `unprotected` or `any`.
  std::optional<InterfaceKind> kind(const AadlProperty& p);
  /// A non-negative integer that fits 32 bits.
  std::optional<std::uint32_t> count(const AadlProperty& p);
  /// `100 ms` (units ps, ns, us, ms, sec, min, hr) in milliseconds.
  std::optional<Milliseconds> time(const AadlProperty& p);
  /// `0 ms .. 10 ms` in milliseconds.
  std::optional<std::pair<Milliseconds, Milliseconds>> time_range(const AadlProperty& p);

 private:
  /// Reads a time at `tokens[pos]` and moves `pos` past it.
  std::optional<Milliseconds> time_at(const AadlProperty& p, std::size_t& pos);
  void expected(const AadlProperty& p, std::size_t pos, const std::string& what);

  AadlErrors& errors_;
};

}  // namespace smcbip::taste2bip::detail
