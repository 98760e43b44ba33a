// Table images of 15- and 16-bit probes (up to 131 104 bytes) and why format 2 guards them with a
// CRC-32C: the CRC-16 of format 1 cannot see some two-bit errors in an image that large.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {
namespace {

std::vector<std::uint8_t> bytesOf(const std::string& text) {
    return {text.begin(), text.end()};
}

/// A 16-bit table of code = 32767.5 + 90 d + 1e-4 d³ (d in µm, ±300 µm), exact points.
Linearisation sixteenBitTable() {
    std::vector<CalibrationPoint> points;
    for (int i = 0; i <= 30; ++i) {
        const double um = -300.0 + 20.0 * i;
        points.push_back({um, 32767.5 + 90.0 * um + 1.0e-4 * um * um * um, 0});
    }
    return linearise(points, 16, 3);
}

void flipBit(std::vector<std::uint8_t>& bytes, std::size_t bit) {
    bytes[bit / 8] ^= static_cast<std::uint8_t>(0x80U >> (bit % 8));
}

/// Smallest d >= 1 with x^d = 1 modulo the CRC polynomial x^width + poly (non-reflected), searched
/// up to `limit`; 0 when none. A two-bit error d bits apart escapes the CRC exactly when d is a
/// multiple of this order (the CRC of the error pattern x^i (x^d + 1) is zero).
std::uint64_t orderOfX(std::uint64_t poly, int width, std::uint64_t limit) {
    const std::uint64_t top = std::uint64_t{1} << width;
    std::uint64_t r = 1;
    for (std::uint64_t d = 1; d <= limit; ++d) {
        r <<= 1;
        if (r & top) r = (r ^ poly) & (top - 1);
        if (r == 1) return d;
    }
    return 0;
}

TEST(Crc32c, CheckValueAndContinuation) {
    // Greg Cook's CRC catalogue, CRC-32/ISCSI: check 0xE3069283; RFC 3720 B.4: 32 bytes of zeros
    // give 0x8A9136AA, 32 bytes of 0xFF give 0x62A8AB43.
    EXPECT_EQ(crc32c(bytesOf("123456789")), 0xE3069283U);
    EXPECT_EQ(crc32c(std::vector<std::uint8_t>(32, 0x00)), 0x8A9136AAU);
    EXPECT_EQ(crc32c(std::vector<std::uint8_t>(32, 0xFF)), 0x62A8AB43U);
    EXPECT_EQ(crc32c(bytesOf("56789"), crc32c(bytesOf("1234"))), 0xE3069283U);
    EXPECT_EQ(crc32c({}), 0U);
}

TEST(Crc32c, SeesEveryTwoBitErrorInAQuarterMebibyteWhereCrc16IsBlindAt32767Bits) {
    // Koopman, "32-bit cyclic redundancy codes for Internet applications" (DSN 2002): CCITT-16
    // = (x + 1) times a primitive polynomial of degree 15, so x has order 2^15 − 1 = 32767 and two
    // flipped bits 32767 apart cancel; CRC-32C keeps Hamming distance 4 up to 2^31 − 1 bits.
    EXPECT_EQ(orderOfX(0x1021, 16, 1'000'000), 32767U);
    const std::uint64_t imageBits = 8ULL * 256 * 1024;   // the largest image of probe protocol 2
    EXPECT_EQ(orderOfX(0x1EDC6F41, 32, imageBits), 0U);  // no two-bit error escapes
    // Both polynomials have an even number of terms, i.e. the factor (x + 1): every error of an
    // odd number of bits (one, three, ...) is detected. With the line above: every error of up to
    // three bits in a 256 KiB image is seen by CRC-32C.
    EXPECT_EQ(std::popcount((1ULL << 32) | 0x1EDC6F41ULL) % 2, 0);
    EXPECT_EQ(std::popcount((1ULL << 16) | 0x1021ULL) % 2, 0);
}

TEST(TableImage, Format1OfA16BitTableAcceptsATwoBitErrorFormat2RefusesIt) {
    const Linearisation lin = sixteenBitTable();
    const TableImageInfo info{3, 1'741'900'000, 0, 3};
    std::vector<std::uint8_t> old = encodeTableImage(lin.table, info, kTableImageFormatCrc16);
    std::vector<std::uint8_t> now = encodeTableImage(lin.table, info);
    ASSERT_EQ(old.size(), tableImageBytes(16, kTableImageFormatCrc16));
    ASSERT_EQ(now.size(), tableImageBytes(16));
    // Two bits 32767 apart inside the entries (bit 8000 of the stream = entry byte 1000 - 32).
    for (auto* image : {&old, &now}) {
        flipBit(*image, 8000);
        flipBit(*image, 8000 + 32767);
    }
    EXPECT_NO_THROW(decodeTableImage(old));  // the corruption goes unseen: entries are wrong
    EXPECT_NE(decodeTableImage(old).table.entries, lin.table.entries);
    try {
        decodeTableImage(now);
        FAIL() << "format 2 accepted a corrupt image";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("CRC mismatch"), std::string::npos) << e.what();
    }
}

TEST(TableImage, SizesOfBothFormats) {
    // docs/protocols/linearisation-table.md: 32 + 2 · 2^bits (+ 2 for format 1's trailer).
    EXPECT_EQ(tableImageBytes(10), 2080U);
    EXPECT_EQ(tableImageBytes(12), 8224U);
    EXPECT_EQ(tableImageBytes(14), 32800U);
    EXPECT_EQ(tableImageBytes(16), 131104U);
    EXPECT_EQ(tableImageBytes(14, kTableImageFormatCrc16), 32802U);
    EXPECT_EQ(tableImageBytes(16, kTableImageFormatCrc16), 131106U);
    EXPECT_THROW(tableImageBytes(17), std::invalid_argument);
    EXPECT_THROW(tableImageBytes(12, 3), std::invalid_argument);
}

TEST(TableImage, Format1ImagesAreStillReadAndCarryTheirCrc16) {
    const Linearisation lin = sixteenBitTable();
    const TableImageInfo info{9, 0, 1, 3};
    const std::vector<std::uint8_t> image = encodeTableImage(lin.table, info, kTableImageFormatCrc16);
    EXPECT_EQ(image[4], 1);
    const std::uint16_t crc = crc16Ccitt(std::span(image).first(image.size() - 2));
    EXPECT_EQ(tableImageCrc(image), crc);
    const TableImage back = decodeTableImage(image);
    EXPECT_EQ(back.format, 1);
    EXPECT_EQ(back.crc, crc);
    EXPECT_EQ(back.info.version, 9);
    EXPECT_EQ(back.info.plane, 1);
    EXPECT_EQ(back.table.entries, lin.table.entries);
    // A format the program does not know is named.
    std::vector<std::uint8_t> future = encodeTableImage(lin.table, info);
    future[4] = 3;
    try {
        decodeTableImage(future);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("format 3"), std::string::npos) << e.what();
    }
}

TEST(TableImage, Format2CarriesItsCrc32cInTheHeaderSoTheUploadCrcIdentifiesTheImage) {
    const Linearisation lin = sixteenBitTable();
    const std::vector<std::uint8_t> a = encodeTableImage(lin.table, {1, 0, 0, 3});
    const std::vector<std::uint8_t> b = encodeTableImage(lin.table, {2, 0, 0, 3});
    // The CRC field (offset 28) covers everything but itself.
    const std::uint32_t expected = crc32c(std::span(a).subspan(32), crc32c(std::span(a).first(28)));
    EXPECT_EQ(tableImageCrc(a), expected);
    EXPECT_EQ(decodeTableImage(a).crc, expected);
    // A CRC-32C appended at the end would make the CRC over the whole image the same constant
    // for every image (the CRC's residue); in the header it is not, so the upload CRC the
    // mandrel reports back tells the tables apart.
    EXPECT_NE(tableUploadCrc(a), tableUploadCrc(b));
    EXPECT_EQ(tableUploadCrc(a), crc32c(a));
    // The C header names the format and the CRC-32C.
    const std::string header = tableToCHeader(lin.table, {1, 0, 0, 3});
    EXPECT_NE(header.find("#define TT_LIN_TABLE_IMAGE_FORMAT 2"), std::string::npos);
    EXPECT_NE(header.find("#define TT_LIN_TABLE_IMAGE_CRC " + crcText(expected) + "u"), std::string::npos);
}

}  // namespace
}  // namespace tt::core
