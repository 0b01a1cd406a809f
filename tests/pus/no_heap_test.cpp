// The packet path allocates nothing: encoding and decoding every message type under a counting
// global operator new.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <variant>

#include "packets/packets.h"
#include "random_packets.h"

namespace {
std::atomic<std::size_t> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace smcbip::pus {
namespace {

TEST(PusNoHeap, EncodeAndDecodeEveryTypeWithoutAllocating) {
  testing::RandomPackets random(5, Config{});
  std::array<std::uint8_t, 4096> out{};
  std::size_t decoded = 0;
  for (const MessageType& type : message_types()) {
    Packet packet = type.direction == PacketType::Tc ? Packet{random.telecommand(type)}
                                                     : Packet{random.telemetry(type)};
    const std::size_t before = allocations.load();
    auto length = std::visit([&](const auto& p) { return encode(p, Config{}, out); }, packet);
    ASSERT_TRUE(length.ok());
    auto back = decode(std::span<const std::uint8_t>(out.data(), length.value()), Config{});
    ASSERT_TRUE(back.ok());
    auto refused = decode(std::span<const std::uint8_t>(out.data(), length.value() - 1), Config{});
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(allocations.load(), before) << type.name;
    ++decoded;
  }
  EXPECT_EQ(decoded, message_types().size());
  // The counter sees allocations at all: the check above cannot pass vacuously.
  const std::size_t before = allocations.load();
  void* probe = ::operator new(16);  // a direct call, which the compiler may not elide
  EXPECT_EQ(allocations.load(), before + 1);
  ::operator delete(probe);
}

}  // namespace
}  // namespace smcbip::pus
