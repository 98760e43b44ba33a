// The dither check before a current run (issue 13 item 7): the figures by hand from the trapezoid
// V = 8 A / (T (1 + f)) and the screw wind-up 2 F_static / k_screw (core/run/dither_check.h).
#include <gtest/gtest.h>

#include "support/heavy_scenario.h"
#include "core/run/dither_check.h"

namespace tt::core {
namespace {

BoringScenario withDither(double amplitudeMm, double periodS) {
    BoringScenario s = test::heavyBoring();
    s.drive.staticFrictionN = 1070.0;
    s.drive.transmissionStiffnessNPerMm = 5.0e5;
    s.dither = DitherConfig{amplitudeMm, periodS, 0.6};
    s.cut.boreToleranceMm = 0.087;
    return s;
}

TEST(DitherCheck, TooShortAStrokeForThePlcCycleNamesTheSmallestAmplitudeAndPeriod) {
    // A = 0.005 mm, T = 0.2 s: V = 8 * 0.005 / (0.2 * 1.6) = 0.125 mm/s; wind-up 2 * 1070 / 5e5 = 4.28 um, so the
    // slide travels 5.72 um = 0.0458 s = 2.29 cycles of 20 ms < 3. Smallest A: 4.28 um / (2 - 3 * 0.02 * 5 / 0.2)
    // = 8.56 um -> 0.009 mm; smallest T: 3 * 0.02 * 5 * 0.005 / 0.00572 = 0.262 s -> 0.27 s.
    const DitherVerdict v = checkDither(withDither(0.005, 0.2));
    EXPECT_EQ(v.problem, DitherProblem::TooSmallToResolve);
    EXPECT_NEAR(v.plateauSpeedMmPerS, 0.125, 1e-12);
    EXPECT_NEAR(v.slideTravelMm, 0.00572, 1e-12);
    EXPECT_NEAR(v.cyclesAtSpeed, 2.288, 1e-9);
    EXPECT_DOUBLE_EQ(*v.validAmplitudeMm, 0.009);
    EXPECT_DOUBLE_EQ(*v.validPeriodS, 0.27);
    EXPECT_NE(v.reason.find("at least 0.009 mm"), std::string::npos) << v.reason;
    EXPECT_TRUE(checkDither(withDither(0.009, 0.2)).ok());
    EXPECT_TRUE(checkDither(withDither(0.005, 0.27)).problem != DitherProblem::TooSmallToResolve);
}

TEST(DitherCheck, SlowerThanTwiceTheOffsetRateIsRefused) {
    // Rate limit 0.05 mm/s: V must be >= 0.1 mm/s. A = 0.01 mm, T = 1 s: V = 0.05 -> smallest A = 0.1 * 1 / 5 =
    // 0.02 mm, longest T = 5 * 0.01 / 0.1 = 0.5 s; both pass.
    const DitherVerdict v = checkDither(withDither(0.01, 1.0));
    EXPECT_EQ(v.problem, DitherProblem::SlowerThanOffset);
    EXPECT_DOUBLE_EQ(*v.validAmplitudeMm, 0.02);
    EXPECT_DOUBLE_EQ(*v.validPeriodS, 0.5);
    EXPECT_TRUE(checkDither(withDither(0.02, 1.0)).ok());
    EXPECT_TRUE(checkDither(withDither(0.01, 0.5)).ok());
}

TEST(DitherCheck, RippleBeyondTheBoreToleranceIsRefusedOnlyWhenOneIsGiven) {
    // 2 A = 0.1 mm > 0.087 mm: at most 0.043 mm (rounded down to the micrometre).
    const DitherVerdict v = checkDither(withDither(0.05, 0.5));
    EXPECT_EQ(v.problem, DitherProblem::RippleBeyondTolerance);
    EXPECT_DOUBLE_EQ(*v.validAmplitudeMm, 0.043);
    EXPECT_TRUE(checkDither(withDither(0.043, 0.5)).ok());
    BoringScenario noTolerance = withDither(0.05, 0.5);
    noTolerance.cut.boreToleranceMm = 0.0;
    EXPECT_TRUE(checkDither(noTolerance).ok());
    EXPECT_THROW(requireResolvableDither(withDither(0.05, 0.5)), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
