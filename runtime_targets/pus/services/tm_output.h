// The on-board side's outgoing telemetry: the on-board time as CUC, the TM packets' counters
// and a fixed-capacity queue of encoded packets towards the link.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>

#include "packets/packets.h"

namespace smcbip::pus::services {

/// On-board time in milliseconds since the epoch of the CUC time.
using Millis = std::uint64_t;

/// The CUC time of an on-board time under the config (to the nearest fine unit).
CucTime to_cuc(Millis now, const Config& config);
/// The on-board time of a CUC time (to the nearest millisecond).
Millis to_millis(const CucTime& time, const Config& config);

/// The longest TM packet the queue holds.
inline constexpr std::size_t kMaxTmLength = 512;
/// Packets the queue holds before it drops the newest.
inline constexpr std::size_t kTmQueueCapacity = 64;

/// One encoded TM packet.
struct TmPacket {
  std::array<std::uint8_t, kMaxTmLength> bytes{};
  std::size_t length = 0;
  std::span<const std::uint8_t> span() const { return {bytes.data(), length}; }
};

/// Builds TM packets of one application process and queues them (first in, first out):
/// the packet sequence count runs over all its packets, the message type counter per
/// [service, subtype] (ECSS-E-ST-70-41C 7.4.3.2), both wrapping.
class TmOutput {
 public:
  TmOutput(const Config& config, std::uint16_t apid) : config_(config), apid_(apid) {}

  /// Encodes and queues [service, subtype] with `data`, timed `now`, to `destination`; false
  /// (and counted as dropped) when the queue is full or the packet cannot be encoded.
  bool emit(std::uint8_t service, std::uint8_t subtype, const Message& data,
            std::uint16_t destination, Millis now);

  /// The oldest queued packet, or nullptr.
  const TmPacket* front() const;
  /// Removes the oldest queued packet.
  void pop();
  std::size_t size() const { return size_; }
  std::size_t dropped() const { return dropped_; }
  const Config& config() const { return config_; }
  std::uint16_t apid() const { return apid_; }

 private:
  Config config_;
  std::uint16_t apid_;
  std::uint16_t sequence_count_ = 0;
  std::array<std::uint16_t, 256 * 256> type_counters_{};
  std::array<TmPacket, kTmQueueCapacity> queue_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::size_t dropped_ = 0;
};

}  // namespace smcbip::pus::services
