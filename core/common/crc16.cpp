#include "core/common/crc16.h"

namespace tt::core {

std::uint16_t crc16Ccitt(std::span<const std::uint8_t> bytes, std::uint16_t initial) {
    std::uint16_t crc = initial;
    for (const std::uint8_t byte : bytes) {
        crc ^= static_cast<std::uint16_t>(byte) << 8;
        for (int bit = 0; bit < 8; ++bit) {
            const bool top = (crc & 0x8000U) != 0;
            crc = static_cast<std::uint16_t>(crc << 1);
            if (top) crc ^= 0x1021U;
        }
    }
    return crc;
}

}  // namespace tt::core
