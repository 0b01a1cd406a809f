// The on-board component on a virtual clock behind the console's Link.
#include "onboard/virtual_link.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "onboard/onboard_externs.hpp"

namespace smcbip::pus::onboard {

VirtualLink::VirtualLink(engines::Execution& component, engines::DataSlot waiting,
                         std::chrono::nanoseconds cycle)
    : component_(component), waiting_(waiting), cycle_(cycle) {
  set_link([this](std::span<const std::uint8_t> bytes) {
    if (has_peer_) tms_.emplace_back(bytes.begin(), bytes.end());
  });
}

VirtualLink::~VirtualLink() { set_link(nullptr); }

void VirtualLink::send(std::span<const std::uint8_t> bytes) {
  ++received_;
  has_peer_ = true;
  const std::int64_t queued = component_.read(waiting_.atom, waiting_.slot).i;
  if (!push_tc(bytes) ||
      !component_.write(waiting_.atom, waiting_.slot, engines::make_int(queued + 1))) {
    ++dropped_;
  }
}

void VirtualLink::run_until(engines::TimeValue t) {
  const engines::StepOutcome outcome = component_.run_until(t);
  if (outcome.ended && outcome.end == engines::RunEnd::Error) {
    throw std::runtime_error("the component failed: " + std::string(outcome.message));
  }
}

std::optional<std::vector<std::uint8_t>> VirtualLink::receive(std::chrono::milliseconds timeout) {
  const engines::TimeValue deadline = component_.now() + std::chrono::nanoseconds(timeout).count();
  while (tms_.empty() && component_.now() < deadline) {
    const engines::TimeValue before = component_.now();
    run_until(std::min(deadline, before + cycle_.count()));
    if (component_.now() == before) break;  // the run is over: time no longer passes
  }
  if (tms_.empty()) return std::nullopt;
  std::vector<std::uint8_t> tm = std::move(tms_.front());
  tms_.pop_front();
  return tm;
}

std::chrono::steady_clock::time_point VirtualLink::now() const {
  return std::chrono::steady_clock::time_point(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::nanoseconds(component_.now())));
}

}  // namespace smcbip::pus::onboard
