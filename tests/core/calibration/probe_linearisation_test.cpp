// Probe mandrel linearisation (paper 001, way 2): fit of the static characteristic, degree choice
// by cross-validation, monotonicity, the table ADC code -> deflection and its exports.
#include "core/calibration/probe_linearisation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>

#include "core/calibration/calibration_csv.h"
#include "core/calibration/linearisation_image.h"
#include "core/common/crc32c.h"

namespace tt::core {
namespace {

// A known 12-bit characteristic: code = 2047.5 + a1 δ + a2 δ² + a3 δ³, δ in µm.
struct Cubic {
    double a0 = 2047.5, a1 = 3.0, a2 = 2.0e-4, a3 = 3.0e-6;
    double code(double um) const { return a0 + a1 * um + a2 * um * um + a3 * um * um * um; }
    // The true inverse by bisection (the characteristic is increasing: a1 > 0, 3 a1 a3 > a2²).
    double deflection(double code) const {
        double lo = -2000.0, hi = 2000.0;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (this->code(mid) < code ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }
};

template <typename F>
std::vector<CalibrationPoint> sample(F code, double fromUm, double toUm, int count, double noiseCodes, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<CalibrationPoint> points;
    for (int i = 0; i < count; ++i) {
        const double um = fromUm + (toUm - fromUm) * i / (count - 1);
        points.push_back({um, code(um) + noiseCodes * normal(rng), 0});
    }
    return points;
}

TEST(ProbeLinearisation, RecoversAKnownCubicCharacteristicWithNoise) {
    const Cubic truth;
    // 41 points over ±500 µm, ADC noise 1.5 codes RMS (about 0.5 µm).
    const auto points = sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 41, 1.5, 7);
    const Linearisation lin = linearise(points, 12, 3);
    ASSERT_EQ(lin.fit.coefficients.size(), 4);
    // Coefficients back within a few standard errors of the truth.
    EXPECT_NEAR(lin.fit.coefficients(0), truth.a0, 1.0);
    EXPECT_NEAR(lin.fit.coefficients(1), truth.a1, 0.01);
    EXPECT_NEAR(lin.fit.coefficients(2), truth.a2, 1e-5);
    EXPECT_NEAR(lin.fit.coefficients(3), truth.a3, 5e-8);
    ASSERT_EQ(lin.table.entries.size(), 4096u);
    // Table against the true inverse over the calibrated codes: the issue asks below 1 % of the
    // 1000 µm range (10 µm); the noise (0.5 µm per point) allows far less.
    double worst = 0.0;
    for (int code = static_cast<int>(std::ceil(truth.code(-500.0))); code <= static_cast<int>(truth.code(500.0));
         ++code)
        worst = std::max(worst, std::abs(lin.table.deflectionUm(code) - truth.deflection(code)));
    EXPECT_LT(worst, 0.01 * 1000.0);
    EXPECT_LT(worst, 1.0);
    EXPECT_LT(lin.fit.rmsResidualUm, 1.0);
    EXPECT_LT(lin.maxTableErrorUm, 2.0);
    EXPECT_TRUE(lin.fit.monotonicity.monotonic);
    EXPECT_TRUE(lin.fit.monotonicity.increasing);
}

TEST(ProbeLinearisation, AutoPicksDegreeThreeForACubicOverManyNoiseDraws) {
    const Cubic truth;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const auto points = sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 31, 1.5, seed);
        const CharacteristicFit fit = fitCharacteristic(points, 12, kAutoDegree);
        EXPECT_EQ(fit.degree, 3) << "seed " << seed << ": " << fit.choiceReason;
        EXPECT_TRUE(fit.chosenAutomatically);
        ASSERT_EQ(fit.scores.size(), 3u);
        // In-sample residual always falls with the degree; cross-validation is what decides.
        EXPECT_GE(fit.scores[0].rmsResidualUm, fit.scores[1].rmsResidualUm);
        EXPECT_GE(fit.scores[1].rmsResidualUm, fit.scores[2].rmsResidualUm);
    }
}

TEST(ProbeLinearisation, AutoIgnoresDifferencesBelowHalfAnAdcCode) {
    // Almost noiseless codes (0.05 code RMS): leave-one-out errors of degrees 3 and 4 differ by
    // hundredths of a code, which the ADC cannot resolve; the cubic is kept every time.
    const Cubic truth;
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const auto points = sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 21, 0.05, seed);
        const CharacteristicFit fit = fitCharacteristic(points, 12, kAutoDegree);
        EXPECT_EQ(fit.degree, 3) << "seed " << seed << ": " << fit.choiceReason;
    }
}

TEST(ProbeLinearisation, AutoKeepsDegreeTwoForAQuadratic) {
    // code = 2047.5 + 3 δ + 1e-3 δ²: increasing for δ > −1500 µm.
    const auto points =
        sample([](double um) { return 2047.5 + 3.0 * um + 1.0e-3 * um * um; }, -400.0, 400.0, 25, 1.0, 3);
    const CharacteristicFit fit = fitCharacteristic(points, 12, kAutoDegree);
    EXPECT_EQ(fit.degree, 2) << fit.choiceReason;
    EXPECT_NE(fit.choiceReason.find("leave-one-out"), std::string::npos);
}

TEST(ProbeLinearisation, DecreasingCharacteristicGivesADecreasingTable) {
    const auto points =
        sample([](double um) { return 2047.5 - 3.0 * um - 2.0e-6 * um * um * um; }, -500.0, 500.0, 21, 0.5, 4);
    const Linearisation lin = linearise(points, 12, kAutoDegree);
    EXPECT_FALSE(lin.fit.monotonicity.increasing);
    for (std::size_t c = 1; c < lin.table.entries.size(); ++c)
        ASSERT_LE(lin.table.entries[c], lin.table.entries[c - 1]);
    EXPECT_NEAR(lin.table.deflectionUm(2048), 0.0, 0.5);
}

TEST(ProbeLinearisation, RefusesANonMonotonicSetAndSaysWhere) {
    // code = 2047.5 + 3 δ − 1.2e-5 δ³ turns where 3 − 3.6e-5 δ² = 0: δ = ±288.7 µm, inside ±500 µm.
    const auto points =
        sample([](double um) { return 2047.5 + 3.0 * um - 1.2e-5 * um * um * um; }, -500.0, 500.0, 41, 1.0, 5);
    const CharacteristicFit fit = fitCharacteristic(points, 12, 3);
    EXPECT_FALSE(fit.monotonicity.monotonic);
    ASSERT_TRUE(fit.monotonicity.turningDeflectionUm.has_value());
    EXPECT_NEAR(*fit.monotonicity.turningDeflectionUm, -288.7, 5.0);
    try {
        linearise(points, 12, 3);
        FAIL() << "a non-monotonic characteristic must be refused";
    } catch (const LinearisationRefused& e) {
        EXPECT_EQ(e.problem(), LinearisationProblem::NonMonotonic);
        const std::string message = e.what();
        EXPECT_NE(message.find("not monotonic"), std::string::npos) << message;
        EXPECT_NE(message.find("-28"), std::string::npos) << message;
        EXPECT_NE(message.find("inside the calibrated range"), std::string::npos) << message;
    }
}

TEST(ProbeLinearisation, RefusesAFitThatTurnsInsideTheAdcRangeBeyondThePoints) {
    // Same curve calibrated over ±200 µm only: it turns at ±288.7 µm, at code 2047.5 ± 577 (inside 0..4095).
    const auto points =
        sample([](double um) { return 2047.5 + 3.0 * um - 1.2e-5 * um * um * um; }, -200.0, 200.0, 21, 0.2, 6);
    try {
        linearise(points, 12, 3);
        FAIL() << "must refuse";
    } catch (const LinearisationRefused& e) {
        EXPECT_EQ(e.problem(), LinearisationProblem::NonMonotonic);
        EXPECT_NE(std::string(e.what()).find("within the ADC range"), std::string::npos) << e.what();
    }
}

TEST(ProbeLinearisation, RefusesTooFewOrRepeatedPoints) {
    const Cubic truth;
    const auto five = sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 5, 0.0, 1);
    try {
        linearise(five, 12, 3);
        FAIL();
    } catch (const LinearisationRefused& e) {
        EXPECT_EQ(e.problem(), LinearisationProblem::TooFewPoints);
        EXPECT_STREQ(e.what(), "a degree-3 characteristic needs at least 6 calibration points, got 5");
    }
    // Eight readings at only four different references.
    std::vector<CalibrationPoint> repeated;
    for (double um : {-300.0, -100.0, 100.0, 300.0})
        for (int k = 0; k < 2; ++k)
            repeated.push_back({um, truth.code(um) + k, 0});
    try {
        linearise(repeated, 12, 3);
        FAIL();
    } catch (const LinearisationRefused& e) {
        EXPECT_EQ(e.problem(), LinearisationProblem::TooFewPoints);
        EXPECT_STREQ(e.what(), "a degree-3 characteristic needs at least 5 different reference deflections, got 4");
    }
}

TEST(ProbeLinearisation, RefusesBadPointsNamingTheLine) {
    const Cubic truth;
    auto points = sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 11, 0.0, 1);
    points[4].adcCode = 4100.0;
    points[4].line = 6;
    try {
        linearise(points, 12, 3);
        FAIL();
    } catch (const LinearisationRefused& e) {
        EXPECT_EQ(e.problem(), LinearisationProblem::OutOfRange);
        EXPECT_STREQ(e.what(), "line 6: ADC code 4100 is outside 0 .. 4095 of a 12-bit ADC");
    }
    points[4].adcCode = std::nan("");
    EXPECT_THROW(linearise(points, 12, 3), LinearisationRefused);
    points[4].adcCode = 2000.0;
    EXPECT_THROW(linearise(points, 9, 3), LinearisationRefused);  // bits outside 10..16
    EXPECT_THROW(linearise(points, 17, 3), LinearisationRefused);
    EXPECT_THROW(linearise(points, 12, 5), LinearisationRefused);  // degree outside 2..4
    std::vector<CalibrationPoint> flat;
    for (int i = 0; i < 8; ++i)
        flat.push_back({i * 50.0, 1234.0, 0});
    try {
        linearise(flat, 12, 2);
        FAIL();
    } catch (const LinearisationRefused& e) {
        EXPECT_NE(std::string(e.what()).find("does not follow the deflection"), std::string::npos);
    }
}

TEST(ProbeLinearisation, WarnsWhenMostOfTheTableIsExtrapolated) {
    const Cubic truth;
    const auto points = sample([&](double um) { return truth.code(um); }, -100.0, 100.0, 15, 0.3, 9);
    const Linearisation lin = linearise(points, 12, 3);
    EXPECT_GT(lin.extrapolatedEntries, 2000);
    ASSERT_EQ(lin.warnings.size(), 1u);
    EXPECT_NE(lin.warnings[0].find("extrapolated"), std::string::npos);
}

TEST(ProbeLinearisation, SixteenBitTableHasAnEntryPerCode) {
    const auto points =
        sample([](double um) { return 32767.5 + 50.0 * um + 4.0e-5 * um * um * um; }, -500.0, 500.0, 21, 5.0, 2);
    const Linearisation lin = linearise(points, 16, 3);
    EXPECT_EQ(lin.table.entries.size(), 65536u);
    EXPECT_LE(lin.tableResolutionUm, 0.05);
}

TEST(LinearisationImage, RoundTripsAndCarriesTheCrcOfItsContent) {
    const Cubic truth;
    const Linearisation lin =
        linearise(sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 21, 1.0, 1), 12, 3);
    const TableImageInfo info{7, 1'741'900'000, 0, 3};
    const std::vector<std::uint8_t> image = encodeTableImage(lin.table, info);
    // Layout (docs/protocols/linearisation-table.md): 32-byte header with the CRC-32C, 4096 × 2 bytes.
    ASSERT_EQ(image.size(), 32u + 2u * 4096u);
    EXPECT_EQ(std::string(image.begin(), image.begin() + 4), "TTLT");
    EXPECT_EQ(image[4], 2);   // format
    EXPECT_EQ(image[5], 32);  // header bytes
    EXPECT_EQ(image[6], 12);  // ADC bits
    EXPECT_EQ(image[8], 7);   // version, little-endian
    EXPECT_EQ(image[24] | (image[25] << 8), 4096);
    // CRC-32C of every byte but the CRC field itself (offset 28..31).
    const std::uint32_t crc = crc32c(std::span(image).subspan(32), crc32c(std::span(image).first(28)));
    EXPECT_EQ(tableImageCrc(image), crc);
    EXPECT_EQ(image[28] | (image[29] << 8) | (image[30] << 16) | (std::uint32_t{image[31]} << 24), crc);

    const TableImage back = decodeTableImage(image);
    EXPECT_EQ(back.crc, crc);
    EXPECT_EQ(back.info.version, 7u);
    EXPECT_EQ(back.info.createdUnixS, 1'741'900'000);
    EXPECT_EQ(back.info.degree, 3);
    EXPECT_EQ(back.table.entries, lin.table.entries);
    EXPECT_EQ(back.table.scaleNm, lin.table.scaleNm);

    std::vector<std::uint8_t> corrupt = image;
    corrupt[100] ^= 0x01;
    try {
        decodeTableImage(corrupt);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("CRC mismatch"), std::string::npos);
    }
    std::vector<std::uint8_t> cut(image.begin(), image.end() - 10);
    EXPECT_THROW(decodeTableImage(cut), std::invalid_argument);
    std::vector<std::uint8_t> foreign = image;
    foreign[0] = 'X';
    EXPECT_THROW(decodeTableImage(foreign), std::invalid_argument);
}

TEST(LinearisationImage, CsvAndCHeaderExports) {
    const Cubic truth;
    const Linearisation lin =
        linearise(sample([&](double um) { return truth.code(um); }, -500.0, 500.0, 21, 1.0, 1), 10 + 2, 3);
    const std::string csv = tableToCsv(lin.table);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4097);
    EXPECT_EQ(csv.substr(0, 23), "adc_code,deflection_um\n");
    const TableImageInfo info{3, 0, 0, 3};
    const std::string header = tableToCHeader(lin.table, info);
    EXPECT_NE(header.find("#define TT_LIN_TABLE_ENTRIES 4096u"), std::string::npos);
    EXPECT_NE(header.find("static const int16_t tt_lin_table[TT_LIN_TABLE_ENTRIES]"), std::string::npos);
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08X", tableImageCrc(encodeTableImage(lin.table, info)));
    EXPECT_NE(header.find(std::string("#define TT_LIN_TABLE_IMAGE_CRC ") + crc), std::string::npos);
    // Every entry is written: 4096 numbers separated by 4095 commas inside the braces.
    const std::string body = header.substr(header.find('{'), header.find('}') - header.find('{'));
    EXPECT_EQ(std::count(body.begin(), body.end(), ','), 4095);
}

TEST(CalibrationCsv, ReadsPointsWithLineNumbers) {
    const auto points = parseCalibrationCsv(
        "\xEF\xBB\xBF# probe 2, plane X\nadc_code;reference_um\n\n1000;-300\n 2048 ; 0 \n3100;+300.5\n");
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0].line, 4);
    EXPECT_DOUBLE_EQ(points[0].referenceUm, -300.0);
    EXPECT_DOUBLE_EQ(points[0].adcCode, 1000.0);
    EXPECT_DOUBLE_EQ(points[2].referenceUm, 300.5);
    EXPECT_EQ(parseCalibrationCsv(calibrationCsv(points)).size(), 3u);
}

TEST(CalibrationCsv, NamesTheBadLine) {
    auto message = [](const std::string& text) {
        try {
            parseCalibrationCsv(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("reference_um,adc_code\n1,2\n3,x12\n"), "line 3: adc_code 'x12' is not a number");
    EXPECT_EQ(message("reference_um,adc_code\n1,2\n5\n"), "line 3: expected 2 columns, got 1");
    EXPECT_EQ(message("deflection,code\n1,2\n"),
              "line 1: the header must name the columns reference_um and adc_code, got 'deflection,code'");
    EXPECT_EQ(message(""), "the file is empty: expected a header reference_um,adc_code");
    EXPECT_EQ(message("reference_um,adc_code\n"), "the file has a header but no calibration points");
    EXPECT_EQ(message("reference_um,adc_code\nnan,4\n"), "line 2: reference_um 'nan' is not a number");
}

}  // namespace
}  // namespace tt::core
