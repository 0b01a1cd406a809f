// CRC-16/CCITT-FALSE, the packet error control of ECSS-E-ST-70-41C (annex B.1).
#pragma once

#include <cstdint>
#include <span>

namespace smcbip::pus {

/// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no final XOR.
/// `crc16({"123456789"})` is 0x29B1; over a packet that ends with its own CRC it is 0.
std::uint16_t crc16(std::span<const std::uint8_t> bytes, std::uint16_t initial = 0xFFFF);

}  // namespace smcbip::pus
