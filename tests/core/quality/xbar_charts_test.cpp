#include <gtest/gtest.h>

#include <span>
#include <stdexcept>
#include <vector>

#include "core/quality/xbar_charts.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

using test::kPistonRings;

// Montgomery (2009), Example 6.1, X-bar-R chart of the piston rings (Table 6.3): x-double-bar = 74.001,
// R-bar = 0.023, X-bar limits 73.988 .. 74.014, R chart 0 .. 0.049, every subgroup in control. The book
// rounds x-double-bar and R-bar to three decimals before multiplying by A2 = 0.577 and D4 = 2.114, so the
// tolerance is 0.001 mm on the limits (0.0005 mm on the centre lines).
TEST(XbarRChart, PistonRingsMatchMontgomeryExample61) {
    const ControlChart chart = xbarChart(kPistonRings, 5, SubgroupSpread::Range);
    const ChartLimits& l = chart.limits;
    EXPECT_EQ(l.kind, ChartKind::XbarRange);
    ASSERT_EQ(chart.locationMm.size(), 25u);
    EXPECT_EQ(chart.unusedValues, 0u);
    EXPECT_NEAR(l.location.centreMm, 74.001, 0.0005);
    EXPECT_NEAR(l.location.upperMm, 74.014, 0.001);
    EXPECT_NEAR(l.location.lowerMm, 73.988, 0.001);
    EXPECT_NEAR(l.spread.centreMm, 0.023, 0.0005);
    EXPECT_NEAR(l.spread.upperMm, 0.049, 0.001);
    EXPECT_EQ(l.spread.lowerMm, 0.0);  // D3 = 0 for n = 5
    // Book Table 6.3 columns: subgroup 1 x-bar 74.010, R 0.038; subgroup 14 x-bar 73.990, R 0.039.
    EXPECT_NEAR(chart.locationMm[0], 74.010, 0.0005);
    EXPECT_NEAR(chart.spreadMm[0], 0.038, 1e-9);
    EXPECT_NEAR(chart.locationMm[13], 73.990, 0.0005);
    EXPECT_NEAR(chart.spreadMm[13], 0.039, 1e-9);
    EXPECT_TRUE(chart.locationBeyondLimits.empty());
    EXPECT_TRUE(chart.spreadBeyondLimits.empty());
    // Section 6.2, process capability: sigma = R-bar/d2 = 0.023/2.326 = 0.0099 (the exact R-bar 0.02324 gives 0.00999).
    EXPECT_NEAR(l.sigmaWithinMm, 0.0099, 0.0001);
    EXPECT_NEAR(l.locationSigmaMm * 3.0, l.location.upperMm - l.location.centreMm, 1e-12);
}

// Montgomery (2009), Example 6.3, X-bar-s chart of the same data: s-bar = 0.0094, X-bar limits 73.988 ..
// 74.014, s chart 0 .. 0.0196, sigma = s-bar/c4 = 0.0094/0.9400 = 0.0100. Tolerances: 0.001 mm on the X-bar
// limits, 0.0001 mm on s-bar, the s limits and sigma (the book's four-decimal rounding).
TEST(XbarSChart, PistonRingsMatchMontgomeryExample63) {
    const ControlChart chart = xbarChart(kPistonRings, 5, SubgroupSpread::StdDev);
    const ChartLimits& l = chart.limits;
    EXPECT_EQ(l.kind, ChartKind::XbarStdDev);
    EXPECT_NEAR(l.location.upperMm, 74.014, 0.001);
    EXPECT_NEAR(l.location.lowerMm, 73.988, 0.001);
    EXPECT_NEAR(l.spread.centreMm, 0.0094, 0.0001);
    EXPECT_NEAR(l.spread.upperMm, 0.0196, 0.0001);
    EXPECT_EQ(l.spread.lowerMm, 0.0);  // B3 = 0 for n = 5
    EXPECT_NEAR(l.sigmaWithinMm, 0.0100, 0.0001);
    EXPECT_TRUE(chart.locationBeyondLimits.empty());
    EXPECT_TRUE(chart.spreadBeyondLimits.empty());
}

// Phase I on the first 20 subgroups, held for all 25: the limits are exactly those of the first 100 values
// alone, and holding them on the whole series gives the same chart.
TEST(XbarRChart, BaselineLimitsAreHeldForLaterSubgroups) {
    const std::span<const double> all(kPistonRings);
    const ControlChart chart = xbarChart(all, 5, SubgroupSpread::Range, ChartBaseline{0, 20});
    const ChartLimits alone = xbarLimits(all.first(100), 5, SubgroupSpread::Range);
    EXPECT_DOUBLE_EQ(chart.limits.location.upperMm, alone.location.upperMm);
    EXPECT_DOUBLE_EQ(chart.limits.spread.upperMm, alone.spread.upperMm);
    EXPECT_EQ(chart.limits.baselinePointCount, 20u);
    EXPECT_EQ(chart.locationMm.size(), 25u);
    const ControlChart held = xbarChart(all, alone);
    EXPECT_EQ(held.locationMm, chart.locationMm);
    EXPECT_EQ(held.spreadMm, chart.spreadMm);

    // Phase II: five more subgroups with the mean moved up by 0.02 mm (two A2 R-bar) are all flagged.
    std::vector<double> shifted(kPistonRings.begin(), kPistonRings.end());
    for (std::size_t i = 0; i < 25; ++i)
        shifted.push_back(kPistonRings[i] + 0.02);
    const ControlChart later = xbarChart(shifted, alone);
    EXPECT_EQ(later.locationBeyondLimits, (std::vector<std::size_t>{25, 26, 27, 28, 29}));
}

// A tail shorter than a subgroup is left out and counted; a baseline beyond the chart, a subgroup size
// outside 2..25, a value that is not a number and a series without scatter are refused with the reason.
TEST(XbarRChart, BadInputIsRefused) {
    const std::span<const double> all(kPistonRings);
    EXPECT_EQ(xbarChart(all.first(123), 5, SubgroupSpread::Range).unusedValues, 3u);
    EXPECT_THROW(xbarChart(all, 5, SubgroupSpread::Range, ChartBaseline{25, 0}), std::invalid_argument);
    EXPECT_THROW(xbarChart(all, 5, SubgroupSpread::Range, ChartBaseline{20, 10}), std::invalid_argument);
    EXPECT_THROW(xbarChart(all, 5, SubgroupSpread::Range, ChartBaseline{0, 1}), std::invalid_argument);
    EXPECT_THROW(xbarChart(all, 1, SubgroupSpread::Range), std::invalid_argument);
    EXPECT_THROW(xbarChart(all, 26, SubgroupSpread::Range), std::invalid_argument);
    std::vector<double> bad(kPistonRings.begin(), kPistonRings.end());
    bad[7] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(xbarChart(bad, 5, SubgroupSpread::Range), std::invalid_argument);
    EXPECT_THROW(xbarChart(std::vector<double>(20, 74.0), 5, SubgroupSpread::StdDev), std::invalid_argument);
    try {
        xbarChart(all, 30, SubgroupSpread::Range);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("2 to 25"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace tt::core
