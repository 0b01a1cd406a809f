// What the files of Runtime share: interval helpers of the semantics and the frames of
// connector code. Internal to engines/semantics.
#pragma once

#include <algorithm>
#include <bit>

#include "engines/semantics/runtime.h"

namespace smcbip::engines {

namespace detail {

using bipc::Urgency;
using engines::narrow;

inline Urgency stronger(Urgency a, Urgency b) { return a > b ? a : b; }

/// The urgent part of a constraint: lazy none, delayable its closed right end, eager all of it.
inline Interval urgent_part(const Constraint& c) {
  switch (c.urgency) {
    case Urgency::Lazy:
      return Interval::none();
    case Urgency::Delayable:
      if (c.interval.right == kPlusInfinity || c.interval.right_open || c.interval.empty()) {
        return Interval::none();
      }
      return Interval::point(c.interval.right);
    case Urgency::Eager:
      return c.interval;
  }
  return Interval::none();
}

/// How long time may pass from `now` without missing the constraint's urgency.
inline Interval wait(const Constraint& c, TimeValue now) {
  const Interval urgent = urgent_part(c);
  if (urgent.empty()) return Interval::from(now);
  if (urgent.contains(now)) return Interval::point(now);
  // An open left end still bounds the wait at that end (the reference engine's Interval::wait),
  // which makes `x > 5` eager a time-lock at 5.
  if (now <= urgent.left) return {now, urgent.left, false, false};
  return Interval::from(now);
}

/// What connector code runs over: the connectors' values and one of them.
struct PortContext {
  ConnectorValues* connectors;
  const InteractionValue* value;
};

inline bool subset(PortSet a, PortSet b) { return (a & ~b) == 0; }

/// Intersects `raw` with one more chosen offer's constraint, field by field (see narrow).
[[gnu::always_inline]] inline void add_offer_constraint(Constraint& raw, const Constraint& offer) {
  narrow(raw.interval, offer.interval);
  raw.urgency = stronger(raw.urgency, offer.urgency);
}

/// The value chosen for a port parameter taking part in an interaction value.
inline const PortValue& chosen(const InteractionValue& v, Index port) {
  if (port < kPortSetBits && v.ports != 0) {
    const PortSet lower_ports = (PortSet{1} << port) - 1;
    const PortSet below = v.ports & lower_ports;
    // Every lower port taking part (a rendezvous): no count needed, which without a popcount
    // instruction in the baseline target is a library call.
    if (below == lower_ports) return v.choice[port];
    return v.choice[static_cast<std::size_t>(std::popcount(below))];
  }
  // Wider connectors: the choice is in port order.
  return *std::lower_bound(v.choice.begin(), v.choice.end(), port,
                           [](const PortValue& pv, Index p) { return pv.param < p; });
}

/// The frame of connector code (guard, up, down) over one interaction value.
inline Frame connector_frame(InteractionValue& value, const PortContext& context, TimeValue now) {
  Frame f;
  f.connector_data = value.data.data();
  f.port_slot = &ConnectorValues::port_slot;
  f.port_context = &context;
  f.now = now;
  return f;
}

}  // namespace detail

}  // namespace smcbip::engines
