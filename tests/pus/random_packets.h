// Random valid PUS packets for round-trip tests and fuzz seeds (fixed seeds, std::mt19937_64).
#pragma once

#include <cstdint>
#include <random>

#include "packets/packets.h"

namespace smcbip::pus::testing {

/// Draws packets of every supported message type whose fields fit the config's widths.
class RandomPackets {
 public:
  RandomPackets(std::uint64_t seed, const Config& config) : rng_(seed), config_(config) {}

  /// A valid telecommand or telemetry packet of the given message type.
  Telecommand telecommand(const MessageType& type);
  Telemetry telemetry(const MessageType& type);
  /// Application data of the type's shape.
  Message message(const MessageType& type);

  std::mt19937_64& rng() { return rng_; }

 private:
  std::uint64_t bits(std::size_t bytes);
  std::size_t below(std::size_t bound);
  PrimaryHeader primary(PacketType type);
  CucTime time();
  FixedBytes<kMaxEmbeddedTc> embedded_tc();
  Verification verification(const MessageType& type);
  Activities activities(const MessageType& type);
  FileRequest file_request(const MessageType& type);
  FixedBytes<kMaxFileString> file_string();

  std::mt19937_64 rng_;
  Config config_;
};

}  // namespace smcbip::pus::testing
