#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "core/common/tolerance.h"
#include "core/quality/iso286.h"

namespace tt::core {
namespace {

// Limit deviations of shafts from ISO 286-2:2010 Tables 2-17 (the published limits of common classes),
// which follow from ISO 286-1 Tables 1 and 2; the tables are in whole micrometres: tolerance 1e-9 mm.
struct PublishedShaft {
    double nominalMm;
    const char* toleranceClass;
    double esUm;
    double eiUm;
};

TEST(Iso286, ShaftClassesMatchThePublishedLimitDeviations) {
    const PublishedShaft cases[] = {
        {25.0, "h9", 0, -52},      {25.0, "js7", 10, -10},  {25.0, "k6", 15, 2},      {25.0, "g6", -7, -20},
        {25.0, "f7", -20, -41},    {50.0, "h7", 0, -25},    {40.0, "m6", 25, 9},      {30.0, "p6", 35, 22},
        {25.0, "n6", 28, 15},      {10.0, "h6", 0, -9},     {100.0, "e8", -72, -126}, {3.0, "js6", 3, -3},
        {120.0, "d9", -120, -207}, {500.0, "h11", 0, -400}, {18.0, "k8", 27, 0},
    };
    for (const PublishedShaft& c : cases) {
        const ToleranceZone z = iso286ShaftZone(c.nominalMm, c.toleranceClass);
        EXPECT_NEAR(z.upperDeviationMm, c.esUm / 1000.0, 1e-9) << c.nominalMm << " " << c.toleranceClass;
        EXPECT_NEAR(z.lowerDeviationMm, c.eiUm / 1000.0, 1e-9) << c.nominalMm << " " << c.toleranceClass;
        EXPECT_DOUBLE_EQ(z.nominalMm, c.nominalMm);
    }
}

// ISO 286-1:2010 Table 1: IT9 for over 18 up to 30 mm is 52 um; a size on a boundary belongs to the lower
// range (30 mm: 52 um, 30.001 mm: 62 um).
TEST(Iso286, StandardTolerancesAndRangeBoundaries) {
    EXPECT_NEAR(iso286StandardToleranceMm(9, 30.0), 0.052, 1e-12);
    EXPECT_NEAR(iso286StandardToleranceMm(9, 30.001), 0.062, 1e-12);
    EXPECT_NEAR(iso286StandardToleranceMm(7, 3.0), 0.010, 1e-12);
    EXPECT_NEAR(iso286StandardToleranceMm(1, 1.0), 0.0008, 1e-12);
    EXPECT_NEAR(iso286StandardToleranceMm(18, 500.0), 9.7, 1e-12);
}

TEST(Iso286, RejectsWhatTheTablesDoNotCover) {
    EXPECT_THROW(iso286ShaftZone(25.0, "H7"), std::invalid_argument);   // a hole class
    EXPECT_THROW(iso286ShaftZone(25.0, "x7"), std::invalid_argument);   // letter not tabulated here
    EXPECT_THROW(iso286ShaftZone(25.0, "h19"), std::invalid_argument);  // grade beyond IT18
    EXPECT_THROW(iso286ShaftZone(25.0, "h"), std::invalid_argument);
    EXPECT_THROW(iso286ShaftZone(600.0, "h9"), std::invalid_argument);  // beyond 500 mm
    EXPECT_THROW(iso286ShaftZone(0.0, "h9"), std::invalid_argument);
    EXPECT_THROW(iso286StandardToleranceMm(0, 25.0), std::invalid_argument);
}

// An outer diameter: above the upper limit is material left (rework), below the lower limit scrap; the
// limits themselves are inside.
TEST(ToleranceVerdict, OuterDiameter) {
    const ToleranceZone z{25.0, 0.0, -0.052};
    EXPECT_EQ(outerDiameterVerdict(z, 25.0), ToleranceVerdict::Good);
    EXPECT_EQ(outerDiameterVerdict(z, 24.948), ToleranceVerdict::Good);
    EXPECT_EQ(outerDiameterVerdict(z, 25.001), ToleranceVerdict::Rework);
    EXPECT_EQ(outerDiameterVerdict(z, 24.947), ToleranceVerdict::Scrap);
    EXPECT_THROW(outerDiameterVerdict(z, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    EXPECT_EQ(worseVerdict(ToleranceVerdict::Rework, ToleranceVerdict::Scrap), ToleranceVerdict::Scrap);
    EXPECT_EQ(worseVerdict(ToleranceVerdict::Rework, ToleranceVerdict::Good), ToleranceVerdict::Rework);
    EXPECT_EQ(toleranceVerdictFromName(toleranceVerdictName(ToleranceVerdict::Rework)), ToleranceVerdict::Rework);
    EXPECT_FALSE(toleranceVerdictFromName("accepted"));
}

TEST(ToleranceVerdict, ZoneChecks) {
    EXPECT_NO_THROW(checkToleranceZone({25.0, 0.0, -0.052}));
    EXPECT_THROW(checkToleranceZone({25.0, -0.052, 0.0}), std::invalid_argument);
    EXPECT_THROW(checkToleranceZone({-1.0, 0.0, -0.052}), std::invalid_argument);
    EXPECT_THROW(checkToleranceZone({25.0, 200.0, -0.052}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
