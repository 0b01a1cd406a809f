// The BIP atom types that give a TASTE provided interface its timing, as the original
// TASTE-to-BIP translation of ESROCOS does: a cyclic interface is started every period, a
// sporadic one takes the calls into a FIFO of its queue size and starts at most once per MIAT.
// The function's own atom sees only `start` and `done`; its deadline bounds the time between
// them (an invariant: a late function stops time, which `timelock` shows).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace smcbip::taste2bip {

/// How long a provided interface runs, between its `start` and its `done` (TASTE's WCET bounds,
/// in the view): no time; any time in [low, high] (a delayable `done`: a choice, which
/// simulation plans uniformly); or a draw from the uniform distribution on [low, high]
/// (`@stochastic` on `done`). With Interval and Uniform the wrapper types take two more
/// parameters, `int wcet_low, int wcet_high`.
enum class Wcet { Zero, Interval, Uniform };

/// A parameter of an interface as BIP data: its name and BIP type (`int`, `float`, an extern
/// type's name).
struct BipParameter {
  std::string name;
  std::string type;
};

/// The longest FIFO sporadic_wrapper writes: its slots are written out one by one, so the
/// translation refuses longer queues with a located error.
inline constexpr std::uint32_t kMaxQueueSize = 64;

/// The name of a wrapper type with execution times: `base` with Wcet::Zero, `base_Wcet` with the
/// others (a package may hold both: an interface without WCET in the view runs in no time).
std::string wrapper_type_name(const std::string& base, Wcet wcet);

/// `port type NAME(T1 p1, ...)` for the parameters (none: `port type NAME()`).
std::string port_type(const std::string& name, const std::vector<BipParameter>& parameters);

/// `atom type TASTE_Cyclic(int period, int deadline, int offset)` (wrapper_type_name), times in
/// milliseconds: the first `start` at `offset`, then one every `period` after the previous start
/// (later when the function is busy with another of its interfaces), each followed by the
/// function's `done` within `deadline`. Its ports are of type `call_port` (no parameters).
std::string cyclic_wrapper(const std::string& call_port, Wcet wcet = Wcet::Zero);

/// `atom type NAME(int miat, int deadline)`: a sporadic interface with these parameters and a
/// FIFO of `queue_size` calls. `call` (port type `call_port`, the caller's data) enqueues, or
/// counts the call in `dropped` when the FIFO is full; `start` offers the oldest call's data to
/// the function when the MIAT since the previous start has passed; `done` (port type
/// `done_port`) is the function's return, within `deadline` of its start. `queue_size` is from 1
/// to kMaxQueueSize.
std::string sporadic_wrapper(const std::string& name, const std::string& call_port,
                             const std::string& done_port,
                             const std::vector<BipParameter>& parameters, std::uint32_t queue_size,
                             Wcet wcet = Wcet::Zero);

/// `atom type TASTE_Synchronous()` (with Wcet Interval and Uniform `(int wcet_low, int
/// wcet_high)`): the execution time of a protected or unprotected interface, run in its caller's
/// thread: `start` with the call, `done` with its return (port type `call_port`, no parameters).
/// The function's return and the caller's result are lazy, so the wrapper's `done` gives the
/// return its urgency.
std::string synchronous_wrapper(const std::string& call_port, Wcet wcet);

}  // namespace smcbip::taste2bip
