// What a transition's firing surely changes, from its places, guard and action.
#include "bipc/ir/state_change.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "bipc/ir/data_guard.h"
#include "bipc/ir/simple_action.h"

namespace smcbip::bipc::ir {

namespace {

bool places_differ(const Transition& transition) {
  std::vector<Index> from = transition.from, to = transition.to;
  std::sort(from.begin(), from.end());
  std::sort(to.begin(), to.end());
  from.erase(std::unique(from.begin(), from.end()), from.end());
  to.erase(std::unique(to.begin(), to.end()), to.end());
  return from != to;
}

/// A datum's value as the action leaves it, relative to the values before the action.
struct AssignedValue {
  enum class Kind : std::uint8_t { Shifted, Literal, Unknown } kind = Kind::Shifted;
  Index source = 0;          // Shifted: the datum whose earlier value it adds `offset` to
  std::uint64_t offset = 0;  // Shifted: wrapping, as the interpreter's Add
  std::int64_t literal = 0;  // Literal
};

/// The data the guard's leading comparisons pin to a literal: `d == k` or `k == d`.
std::map<Index, std::int64_t> pinned_data(const Code& guard) {
  std::map<Index, std::int64_t> pinned;
  const std::optional<LeadingComparison> leading = leading_comparison(guard);
  if (!leading) return pinned;
  for (std::uint8_t i = 0; i < leading->count; ++i) {
    const IntComparison& test = leading->tests[i];
    if (test.op != Op::Eq) continue;
    using Kind = IntOperand::Kind;
    if (test.left.kind == Kind::AtomData && test.right.kind == Kind::Literal) {
      pinned.emplace(test.left.index, test.right.literal);
    } else if (test.right.kind == Kind::AtomData && test.left.kind == Kind::Literal) {
      pinned.emplace(test.right.index, test.left.literal);
    }
  }
  return pinned;
}

/// The values the action leaves in the data it assigns, by datum.
std::map<Index, AssignedValue> assigned_values(const std::vector<SimpleAssignment>& action) {
  std::map<Index, AssignedValue> now;
  const auto value_of = [&](Index datum) {
    const auto found = now.find(datum);
    return found == now.end() ? AssignedValue{AssignedValue::Kind::Shifted, datum, 0, 0}
                              : found->second;
  };
  for (const SimpleAssignment& assignment : action) {
    using Kind = SimpleAssignment::Kind;
    AssignedValue value{AssignedValue::Kind::Unknown};
    if (assignment.kind == Kind::Int) {
      value = {AssignedValue::Kind::Literal, 0, 0, assignment.literal};
    } else if (assignment.kind == Kind::AddInt) {
      value = value_of(assignment.source);
      const auto k = static_cast<std::uint64_t>(assignment.literal);
      if (value.kind == AssignedValue::Kind::Shifted) value.offset += k;
      if (value.kind == AssignedValue::Kind::Literal) {
        value.literal = static_cast<std::int64_t>(static_cast<std::uint64_t>(value.literal) + k);
      }
    } else if (assignment.kind == Kind::ClockSet) {
      continue;  // clocks are not part of the compared state
    }
    now[assignment.target] = value;
  }
  return now;
}

}  // namespace

bool always_changes_state(const Transition& transition, bool written_before) {
  if (places_differ(transition)) return true;
  const std::optional<std::vector<SimpleAssignment>> action = simple_action(transition.action);
  if (!action) return false;
  const std::map<Index, std::int64_t> pinned = pinned_data(transition.guard);
  for (const auto& [datum, value] : assigned_values(*action)) {
    if (value.kind == AssignedValue::Kind::Shifted && value.source == datum && value.offset != 0 &&
        !written_before) {
      return true;
    }
    const auto pin = pinned.find(datum);
    if (value.kind == AssignedValue::Kind::Literal && pin != pinned.end() &&
        pin->second != value.literal) {
      return true;
    }
  }
  return false;
}

}  // namespace smcbip::bipc::ir
