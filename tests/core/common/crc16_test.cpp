#include "core/common/crc16.h"

#include <gtest/gtest.h>

#include <array>
#include <string_view>

namespace tt::core {
namespace {

std::span<const std::uint8_t> bytesOf(std::string_view s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// Reference: Greg Cook, "Catalogue of parametrised CRC algorithms", CRC-16/IBM-3740
// (a.k.a. CRC-16/CCITT-FALSE): check value of "123456789" is 0x29B1.
TEST(Crc16Ccitt, MatchesCatalogueCheckValue) {
    EXPECT_EQ(crc16Ccitt(bytesOf("123456789")), 0x29B1);
}

TEST(Crc16Ccitt, EmptyInputIsInitialValue) {
    EXPECT_EQ(crc16Ccitt({}), 0xFFFF);
}

TEST(Crc16Ccitt, ContinuesAcrossChunks) {
    const std::uint16_t first = crc16Ccitt(bytesOf("12345"));
    EXPECT_EQ(crc16Ccitt(bytesOf("6789"), first), 0x29B1);
}

TEST(Crc16Ccitt, DetectsSingleBitFlip) {
    std::array<std::uint8_t, 4> frame{0x10, 0x20, 0x30, 0x40};
    const std::uint16_t good = crc16Ccitt(frame);
    frame[2] ^= 0x01;
    EXPECT_NE(crc16Ccitt(frame), good);
}

}  // namespace
}  // namespace tt::core
