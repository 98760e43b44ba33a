// A table image whose header is out of the specification (docs/protocols/linearisation-table.md) but
// whose CRC is valid (the writer computed it over the wrong fields) is refused, naming the field
// (issue 17, item 3).
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {
namespace {

/// A 12-bit table of code = 2047.5 + 3 d + 3e-6 d³ (d in µm, ±300 µm): deflection grows with the code.
LinearisationTable table12() {
    std::vector<CalibrationPoint> points;
    for (int i = 0; i <= 30; ++i) {
        const double um = -300.0 + 20.0 * i;
        points.push_back({um, 2047.5 + 3.0 * um + 3.0e-6 * um * um * um, 0});
    }
    return linearise(points, 12, 3).table;
}

/// Writes `value` (little-endian, `bytes` long) at `offset` and makes the image's CRC valid again.
void setField(std::vector<std::uint8_t>& image, std::size_t offset, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i)
        image[offset + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF);
    if (image[4] == kTableImageFormatCrc16) {
        const std::uint16_t crc = crc16Ccitt(std::span<const std::uint8_t>(image).first(image.size() - 2));
        image[image.size() - 2] = static_cast<std::uint8_t>(crc & 0xFF);
        image[image.size() - 1] = static_cast<std::uint8_t>(crc >> 8);
    } else {
        const std::span<const std::uint8_t> all(image);
        const std::uint32_t crc = crc32c(all.subspan(32), crc32c(all.first(28)));
        for (std::size_t i = 0; i < 4; ++i)
            image[28 + i] = static_cast<std::uint8_t>((crc >> (8 * i)) & 0xFF);
    }
}

/// decodeTableImage refuses `image`, and its message contains `phrase`.
void expectRefused(const std::vector<std::uint8_t>& image, const std::string& phrase) {
    try {
        decodeTableImage(image);
        ADD_FAILURE() << "accepted; expected a refusal with: " << phrase;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
}

class TableImageFields : public ::testing::Test {
protected:
    const LinearisationTable m_table = table12();
    const std::vector<std::uint8_t> m_image = encodeTableImage(m_table, {4, 1'741'900'000, 1, 3});
};

TEST_F(TableImageFields, TheImageAsWrittenIsAccepted) {
    const TableImage image = decodeTableImage(m_image);
    EXPECT_EQ(image.info.plane, 1);
    EXPECT_EQ(image.info.version, 4);
    EXPECT_EQ(image.info.degree, 3);
    EXPECT_EQ(image.table.entries, m_table.entries);
}

TEST_F(TableImageFields, EachFieldOutsideTheSpecificationIsRefusedByName) {
    struct Case {
        std::size_t offset;
        std::uint64_t value;
        int bytes;
        const char* phrase;
    };
    const Case cases[] = {
        {7, 2, 1, "image field 'bending plane' (offset 7) is 2; the specification allows 0 (X) or 1 (Y)"},
        {8, 0, 2, "image field 'table version' (offset 8) is 0"},
        {10, 0x0101, 2, "image field 'reserved' (offset 10) is 257"},
        {12, static_cast<std::uint64_t>(-5LL), 8, "image field 'created' (offset 12) is -5"},
        {12, 300'000'000'000ULL, 8, "image field 'created' (offset 12) is 300000000000"},
        {20, 7, 2, "image field 'scale' (offset 20) is 7"},
        {20, 0, 2, "image field 'scale' (offset 20) is 0"},
        {22, 1, 1, "image field 'degree' (offset 22) is 1"},
        {22, 9, 1, "image field 'degree' (offset 22) is 9"},
        {23, 0x80, 1, "image field 'flags' (offset 23) is 128; the specification allows bit 0 only"},
        // Bit 0 says "decreasing" but the entries grow with the code.
        {23, 0x01, 1, "image field 'flags' (offset 23) is 1; the specification allows bit 0 = 0"},
    };
    for (const Case& c : cases) {
        std::vector<std::uint8_t> image = m_image;
        setField(image, c.offset, c.value, c.bytes);
        EXPECT_EQ(tableImageCrc(image), crc32c(std::span<const std::uint8_t>(image).subspan(32),
                                               crc32c(std::span<const std::uint8_t>(image).first(28))))
            << "the CRC must be valid";
        expectRefused(image, c.phrase);
    }
}

TEST_F(TableImageFields, Format1ReservedBytesAreChecked) {
    std::vector<std::uint8_t> image = encodeTableImage(m_table, {4, 0, 0, 3}, kTableImageFormatCrc16);
    EXPECT_NO_THROW(decodeTableImage(image));
    setField(image, 28, 0xDEAD, 4);
    expectRefused(image, "image field 'reserved (format 1)' (offset 28) is 57005");
}

TEST_F(TableImageFields, AnOutOfSpecIdentificationIsNeverWritten) {
    EXPECT_THROW(encodeTableImage(m_table, {4, 0, 2, 3}), std::invalid_argument);  // plane 2
    EXPECT_THROW(encodeTableImage(m_table, {0, 0, 0, 3}), std::invalid_argument);  // version 0
    EXPECT_THROW(encodeTableImage(m_table, {1, -1, 0, 3}), std::invalid_argument);
    EXPECT_THROW(encodeTableImage(m_table, {1, 0, 0, 5}), std::invalid_argument);
    EXPECT_NO_THROW(encodeTableImage(m_table, {1, 0, 0, 0}));  // degree 0: not recorded
}

}  // namespace
}  // namespace tt::core
