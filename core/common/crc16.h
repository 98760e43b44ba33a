#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace tt::core {

/// CRC-16/CCITT-FALSE (polynomial 0x1021, initial value 0xFFFF, no reflection, no final XOR).
/// Used by the probe-mandrel frame protocol and the linearisation table image.
/// Check value: crc16Ccitt("123456789") == 0x29B1 (Greg Cook's CRC catalogue, "CRC-16/IBM-3740").
std::uint16_t crc16Ccitt(std::span<const std::uint8_t> bytes, std::uint16_t initial = 0xFFFF);

}  // namespace tt::core
