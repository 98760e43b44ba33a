#include "devices/parsers/gauge_ascii.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "devices/parsers/line_framer.h"

namespace tt::devices {
namespace {

std::vector<std::uint8_t> bytes(const std::string& s) {
    return {s.begin(), s.end()};
}

TEST(GaugeAscii, ParsesTheDataCableLine) {
    const auto r = parseAsciiGaugeLine("01A+00026.812");
    ASSERT_TRUE(r) << r.error();
    EXPECT_EQ(r->channel, 1);
    EXPECT_EQ(r->item, 'A');
    EXPECT_DOUBLE_EQ(r->value, 26.812);
    EXPECT_EQ(r->decimals, 3);
    EXPECT_FALSE(r->unit.has_value());  // this format carries no unit
}

TEST(GaugeAscii, ParsesTheManualsExamplesAndNegativeValues) {
    // Mitutoyo No. 99MAF600B, 6.2.2: mm 0.001 -> 01A+0000.123; inch 0.00005 -> 01A+00.12345.
    EXPECT_DOUBLE_EQ(parseAsciiGaugeLine("01A+0000.123")->value, 0.123);
    const auto inch = parseAsciiGaugeLine("01A+00.12345");
    ASSERT_TRUE(inch);
    EXPECT_DOUBLE_EQ(inch->value, 0.12345);
    EXPECT_EQ(inch->decimals, 5);
    const auto negative = parseAsciiGaugeLine("02B-00001.500");
    ASSERT_TRUE(negative);
    EXPECT_EQ(negative->channel, 2);
    EXPECT_EQ(negative->item, 'B');
    EXPECT_DOUBLE_EQ(negative->value, -1.5);
    EXPECT_DOUBLE_EQ(parseAsciiGaugeLine("01A+26")->value, 26.0);
}

TEST(GaugeAscii, TakesAUnitSuffixWhenTheInterfaceSendsOne) {
    EXPECT_EQ(parseAsciiGaugeLine("01A+00026.812mm")->unit, LengthUnit::Millimetre);
    EXPECT_EQ(parseAsciiGaugeLine("01A+001.0556 in")->unit, LengthUnit::Inch);
    EXPECT_DOUBLE_EQ(parseAsciiGaugeLine("01A+001.0556IN")->value, 1.0556);
}

TEST(GaugeAscii, RefusesMalformedLinesWithAReason) {
    for (const char* bad : {"", "01A+", "1A+26.8", "01a+26.8", "01A*26.812", "01A+26..8", "01A+2x.812", "01A+.",
                            "01A+0000000000000.1", "01A+26.8 kg"}) {
        const auto r = parseAsciiGaugeLine(bad);
        EXPECT_FALSE(r) << bad;
        EXPECT_FALSE(r.error().empty()) << bad;
    }
    EXPECT_NE(parseAsciiGaugeLine("01A*26.812").error().find("sign"), std::string::npos);
}

TEST(GaugeAscii, FormatsLikeTheInstrumentAndRoundTrips) {
    EXPECT_EQ(formatAsciiGaugeLine(26.812, 3), "01A+00026.812\r");
    EXPECT_EQ(formatAsciiGaugeLine(-0.1234, 4, 8), "01A-000.1234\r");
    EXPECT_EQ(formatAsciiGaugeLine(-0.0001, 3), "01A+00000.000\r");  // rounds to zero: no negative zero
    EXPECT_EQ(formatAsciiGaugeLine(1.0, 3, 9, 1, 'A', LengthUnit::Inch), "01A+00001.000in\r");
    for (double v : {0.0, 0.001, 26.8125, 99999.999, -123.456}) {
        std::string line = formatAsciiGaugeLine(v, 3);
        line.pop_back();
        const auto r = parseAsciiGaugeLine(line);
        ASSERT_TRUE(r) << line;
        EXPECT_NEAR(r->value, v, 0.0005) << line;  // quantised to the 0.001 resolution
    }
    EXPECT_THROW(formatAsciiGaugeLine(1e7, 3), std::invalid_argument);
}

TEST(LineFramer, SplitsOnCarriageReturnAcrossChunksAndIgnoresLineFeed) {
    LineFramer framer;
    EXPECT_TRUE(framer.feed(bytes("01A+000")).empty());
    auto lines = framer.feed(bytes("26.812\r\n01A+00026.813\r\r"));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "01A+00026.812");
    EXPECT_EQ(lines[1], "01A+00026.813");
    EXPECT_EQ(framer.pending(), 0u);
}

TEST(LineFramer, DiscardsAndCountsOverlongLinesWithoutGrowing) {
    LineFramer framer(16);
    const std::string garbage(1000, 'x');
    EXPECT_TRUE(framer.feed(bytes(garbage)).empty());
    EXPECT_LE(framer.pending(), 16u);
    const auto lines = framer.feed(bytes("\r01A+00026.812\r"));
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "01A+00026.812");
    EXPECT_EQ(framer.overlongLines(), 1u);
}

}  // namespace
}  // namespace tt::devices
