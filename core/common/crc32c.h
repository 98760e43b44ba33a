#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace tt::core {

/// CRC-32C (Castagnoli: polynomial 0x1EDC6F41, reflected 0x82F63B78, initial value 0xFFFFFFFF,
/// input and output reflected, final XOR 0xFFFFFFFF). Guards the large linearisation table
/// images (format 2, up to 256 KiB) and their upload in probe protocol 2, where CRC-16 is too
/// weak (docs/DECISIONS.md, "Table images and uploads over 64 KiB: CRC-32C").
/// Check value: crc32c("123456789") == 0xE3069283 (Greg Cook's CRC catalogue, "CRC-32/ISCSI").
/// `previous` continues a CRC over several pieces: crc32c(b, crc32c(a)) == crc32c(a + b).
std::uint32_t crc32c(std::span<const std::uint8_t> bytes, std::uint32_t previous = 0);

}  // namespace tt::core
