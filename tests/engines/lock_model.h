// A model whose runs end in a deadlock or a time-lock (root Top()), for the engines' exploration
// and for checking properties over such runs.
#pragma once

namespace smcbip::tests {

// From s0 the atom `one` moves to s1 (no transition, no invariant: a deadlock) or to s2, whose
// invariant stops time at x = 3 (no transition: a time-lock), both at time 0.
inline constexpr const char* kDeadlockOrTimeLock = R"(package locks
  port type Sig()
  atom type A()
    clock x unit millisecond
    port Sig a(), b()
    place s0, s1, s2
    initial to s0 do { x = 0; }
    on a from s0 to s1
    on b from s0 to s2
    invariant stay_short at s2 provided (x <= 3)
  end
  compound type Top()
    component A one()
  end
end
)";

}  // namespace smcbip::tests
