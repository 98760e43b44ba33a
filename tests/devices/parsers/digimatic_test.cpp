#include "devices/parsers/digimatic.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tt::devices {
namespace {

DigimaticNibbles nibbles(const std::string& hex) {
    DigimaticNibbles n{};
    for (std::size_t i = 0; i < n.size(); ++i)
        n[i] = static_cast<std::uint8_t>(std::stoi(hex.substr(i, 1), nullptr, 16));
    return n;
}

TEST(Digimatic, DecodesTheManualsExamples) {
    // Mitutoyo LSM-6200 manual No. 99MBC095A, 6.2.1.5: FFFF 0 210765 4 0 = +21.0765 mm.
    const auto a = decodeDigimatic(nibbles("FFFF021076540"));
    ASSERT_TRUE(a) << a.error();
    EXPECT_DOUBLE_EQ(a->value, 21.0765);
    EXPECT_EQ(a->decimals, 4);
    EXPECT_EQ(a->unit, LengthUnit::Millimetre);
    // Measuring projector manual No. 99MBA043A: FFFF 8 012345 3 0 = -12.345 mm.
    const auto b = decodeDigimatic(nibbles("FFFF801234530"));
    ASSERT_TRUE(b) << b.error();
    EXPECT_DOUBLE_EQ(b->value, -12.345);
    // QM-Height manual No. 99MAF600B: 0.123 mm = FFFF 0 000123 3 0.
    EXPECT_DOUBLE_EQ(decodeDigimatic(nibbles("FFFF000012330"))->value, 0.123);
}

TEST(Digimatic, ReadsTheUnitAndTheJudgementNibble) {
    const auto inch = decodeDigimatic(nibbles("FFFF001055641"));
    ASSERT_TRUE(inch);
    EXPECT_EQ(inch->unit, LengthUnit::Inch);
    EXPECT_DOUBLE_EQ(inch->value, 1.0556);
    EXPECT_EQ(decodeDigimatic(nibbles("FFFF002681233"))->judgement, DigimaticJudgement::Go);
    EXPECT_EQ(decodeDigimatic(nibbles("FFFF002681237"))->unit, LengthUnit::Inch);
    EXPECT_EQ(decodeDigimatic(nibbles("FFFF002681237"))->judgement, DigimaticJudgement::BelowLimit);
}

TEST(Digimatic, RefusesBadNibblesWithTheirPosition) {
    EXPECT_NE(decodeDigimatic(nibbles("EFFF002681230")).error().find("FFFF"), std::string::npos);
    EXPECT_NE(decodeDigimatic(nibbles("FFFF102681230")).error().find("sign"), std::string::npos);
    EXPECT_NE(decodeDigimatic(nibbles("FFFF002A81230")).error().find("d8"), std::string::npos);
    EXPECT_NE(decodeDigimatic(nibbles("FFFF002681260")).error().find("decimal"), std::string::npos);
    EXPECT_NE(decodeDigimatic(nibbles("FFFF002681238")).error().find("unit"), std::string::npos);
    const std::vector<std::uint8_t> shortFrame(12, 0xF);
    EXPECT_FALSE(decodeDigimatic(shortFrame));
}

TEST(Digimatic, EncodesAndRoundTrips) {
    EXPECT_EQ(encodeDigimatic(21.0765, 4, LengthUnit::Millimetre), nibbles("FFFF021076540"));
    EXPECT_EQ(encodeDigimatic(-12.345, 3, LengthUnit::Millimetre), nibbles("FFFF801234530"));
    for (double v : {0.0, 26.812, -0.001, 999.999}) {
        const auto r = decodeDigimatic(encodeDigimatic(v, 3, LengthUnit::Millimetre));
        ASSERT_TRUE(r);
        EXPECT_NEAR(r->value, v, 1e-9);
    }
    EXPECT_THROW(encodeDigimatic(1000.0, 3, LengthUnit::Millimetre), std::invalid_argument);  // seven digits
}

TEST(DigimaticFramer, SynchronisesOnTheHeaderInRawNibbles) {
    DigimaticFramer framer(DigimaticEncoding::RawNibbles);
    const auto frame = encodeDigimatic(26.812, 3, LengthUnit::Millimetre);
    std::vector<std::uint8_t> stream{0x3, 0x7, 0xF, 0xF, 0x41};     // noise, a broken header, a non-nibble byte
    stream.insert(stream.end(), frame.begin(), frame.begin() + 7);  // a frame cut short ...
    stream.insert(stream.end(), frame.begin(), frame.end());        // ... then two whole ones
    stream.insert(stream.end(), 0xF);                               // five F: still in sync
    stream.insert(stream.end(), frame.begin(), frame.end());
    const auto frames = framer.feed(stream);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0], frame);
    EXPECT_EQ(frames[1], frame);
    EXPECT_EQ(framer.discardedBytes(), 5u + 7u + 1u);
}

TEST(DigimaticFramer, TakesHexTextLinesOfExactlyThirteenDigits) {
    DigimaticFramer framer(DigimaticEncoding::HexText);
    const std::string text = "FFFF002681230\r\nFFFF00268123\rFFFF0026812300\rFFFF0G2681230\rffff801234530\r";
    const auto frames = framer.feed(std::vector<std::uint8_t>(text.begin(), text.end()));
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_DOUBLE_EQ(decodeDigimatic(frames[0])->value, 26.812);
    EXPECT_DOUBLE_EQ(decodeDigimatic(frames[1])->value, -12.345);
    EXPECT_EQ(digimaticHexLine(frames[0]), "FFFF002681230\r");
    EXPECT_EQ(framer.discardedBytes(), 12u + 14u + 13u);
}

}  // namespace
}  // namespace tt::devices
