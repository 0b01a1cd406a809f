// The packet path allocates nothing: encoding and decoding every message type under a counting
// global operator new.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <variant>

#include "counting_new.h"
#include "packets/packets.h"
#include "random_packets.h"

namespace smcbip::pus {
namespace {

TEST(PusNoHeap, EncodeAndDecodeEveryTypeWithoutAllocating) {
  testing::RandomPackets random(5, Config{});
  std::array<std::uint8_t, 4096> out{};
  std::size_t decoded = 0;
  for (const MessageType& type : message_types()) {
    Packet packet = type.direction == PacketType::Tc ? Packet{random.telecommand(type)}
                                                     : Packet{random.telemetry(type)};
    const std::size_t before = testing::allocations.load();
    auto length = std::visit([&](const auto& p) { return encode(p, Config{}, out); }, packet);
    ASSERT_TRUE(length.ok());
    auto back = decode(std::span<const std::uint8_t>(out.data(), length.value()), Config{});
    ASSERT_TRUE(back.ok());
    auto refused = decode(std::span<const std::uint8_t>(out.data(), length.value() - 1), Config{});
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(testing::allocations.load(), before) << type.name;
    ++decoded;
  }
  EXPECT_EQ(decoded, message_types().size());
  // The counter sees allocations at all: the check above cannot pass vacuously.
  const std::size_t before = testing::allocations.load();
  void* probe = ::operator new(16);  // a direct call, which the compiler may not elide
  EXPECT_EQ(testing::allocations.load(), before + 1);
  ::operator delete(probe);
}

}  // namespace
}  // namespace smcbip::pus
