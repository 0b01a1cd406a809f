// The console's link to the on-board component simulated on a virtual clock: what the deployed
// pus_onboard does with UDP and real time, done with the model's clock, so that a console
// script runs against the model in simulation exactly as it runs against the program.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "console/link.h"
#include "engines/api/execution.h"

namespace smcbip::pus::onboard {

class VirtualLink final : public console::Link {
 public:
  /// Drives `component` (started, the ground off) whose uplink counts its TCs in `waiting`, in
  /// steps of `cycle` of model time as pus_onboard's loop does; installs itself as the
  /// extern layer's link.
  VirtualLink(engines::Execution& component, engines::DataSlot waiting,
              std::chrono::nanoseconds cycle);
  ~VirtualLink() override;
  VirtualLink(const VirtualLink&) = delete;
  VirtualLink& operator=(const VirtualLink&) = delete;

  /// Puts a TC in the model's uplink at the current model time, as a datagram received.
  void send(std::span<const std::uint8_t> bytes) override;
  /// The oldest TM flushed and not yet taken, running the model until one comes or `timeout`
  /// of model time has passed.
  std::optional<std::vector<std::uint8_t>> receive(std::chrono::milliseconds timeout) override;
  /// The model's time, as the session's clock.
  std::chrono::steady_clock::time_point now() const override;

  /// Runs the model on to `t` (nanoseconds of model time); throws if the component fails.
  void run_until(engines::TimeValue t);
  std::uint64_t received() const { return received_; }
  std::uint64_t dropped() const { return dropped_; }

 private:
  engines::Execution& component_;
  engines::DataSlot waiting_;
  std::chrono::nanoseconds cycle_;
  bool has_peer_ = false;  ///< as pus_onboard: no TM goes anywhere before the first TC
  std::deque<std::vector<std::uint8_t>> tms_;
  std::uint64_t received_ = 0, dropped_ = 0;
};

}  // namespace smcbip::pus::onboard
