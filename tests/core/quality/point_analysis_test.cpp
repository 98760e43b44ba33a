#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "core/quality/point_analysis.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

MeasuredSeries seriesOf(const std::vector<double>& values, std::int64_t firstPart) {
    MeasuredSeries s;
    for (std::size_t i = 0; i < values.size(); ++i) {
        s.valuesMm.push_back(values[i]);
        s.partNumbers.push_back(firstPart + static_cast<std::int64_t>(i));
        s.timesS.push_back(1.7e9 + 60.0 * static_cast<double>(i));
    }
    return s;
}

// The piston rings (Montgomery Table 6.3) as one control point, parts 1001..1125: the analysis holds the
// X-bar-R chart of Example 6.1 (the same limits as xbarChart, 0.001 mm of the book) and the capability study
// with R-bar/d2 as the within sigma.
TEST(PointAnalysis, PistonRingsChartAndCapability) {
    PointAnalysisSettings settings;
    settings.subgroupSize = 5;
    settings.spec = SpecLimits{73.95, 74.05, {}};
    const PointAnalysis a = analysePoint(seriesOf(test::kPistonRings, 1001), settings);
    EXPECT_EQ(a.count, 125u);
    EXPECT_EQ(a.firstPart, 1001);
    EXPECT_EQ(a.lastPart, 1125);
    EXPECT_DOUBLE_EQ(a.lastTimeS, 1.7e9 + 60.0 * 124.0);
    EXPECT_EQ(a.chart.limits.kind, ChartKind::XbarRange);
    EXPECT_NEAR(a.chart.limits.location.upperMm, 74.014, 0.001);
    ASSERT_TRUE(a.capability);
    EXPECT_EQ(a.capability->within, WithinSigmaMethod::Range);
    EXPECT_DOUBLE_EQ(a.capability->sigmaWithinMm, a.chart.limits.sigmaWithinMm);
    // Example 6.1: no subgroup beyond the limits, so no rule 1.
    for (const PointViolation& v : a.violations)
        EXPECT_NE(v.violation.rule, 1);
}

// A violation names its parts: with held I-MR limits (centre 10, sigma 1) a value at 13.5 on part 120 is
// rule 1 at that part; with subgroups of 2 (X-bar, held centre 10, sigma of the mean 1) the subgroup
// of values 21 and 22 (parts 150 and 151) at 13.5 is rule 1 (point 10) with both parts.
TEST(PointAnalysis, ViolationsCarryTheirParts) {
    std::vector<double> values;
    constexpr double kPattern[4] = {0.5, -1.5, -0.5, 1.5};
    for (int i = 0; i < 40; ++i)
        values.push_back(10.0 + kPattern[i % 4]);
    values[20] = 13.5;
    PointAnalysisSettings settings;
    settings.heldLimits =
        ChartLimits{ChartKind::IndividualsMovingRange, 1, {7.0, 10.0, 13.0}, {0.0, 1.128, 3.686}, 1.0, 1.0, 0, 40};
    const PointAnalysis a = analysePoint(seriesOf(values, 100), settings);
    ASSERT_EQ(a.violations.size(), 1u);
    EXPECT_EQ(a.violations[0].violation.rule, 1);
    EXPECT_EQ(a.violations[0].partNumbers, std::vector<std::int64_t>{120});
    EXPECT_FALSE(a.capability);

    std::vector<double> pairs;
    for (int i = 0; i < 40; ++i)
        pairs.push_back(10.0 + kPattern[(i / 2) % 4]);
    pairs[20] = pairs[21] = 13.5;
    settings.heldLimits = ChartLimits{ChartKind::XbarRange, 2, {7.0, 10.0, 13.0}, {0.0, 1.0, 3.267}, 1.414, 1.0, 0, 20};
    const PointAnalysis b = analysePoint(seriesOf(pairs, 130), settings);
    ASSERT_EQ(b.violations.size(), 1u);
    EXPECT_EQ(b.violations[0].violation.points, std::vector<std::size_t>{10});
    EXPECT_EQ(b.violations[0].partNumbers, (std::vector<std::int64_t>{150, 151}));
}

TEST(PointAnalysis, MismatchedSeriesIsRefused) {
    MeasuredSeries s = seriesOf(test::kLoanCosts, 1);
    s.partNumbers.pop_back();
    EXPECT_THROW(analysePoint(s, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
