#include <gtest/gtest.h>

#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/quality/individual_charts.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

using test::kLoanCosts;

// Montgomery (2009), Section 6.4, the mortgage-loan processing costs: x-bar = 300.5, MR-bar = 7.79,
// I chart 279.78 .. 321.22, MR chart 0 .. 25.45; every point in control. The book rounds MR-bar to 7.79
// (exactly 148/19 = 7.7895) and uses d2 = 1.128, D4 = 3.267: tolerance 0.01 on the limits.
TEST(IndividualsChart, LoanCostsMatchMontgomerySection64) {
    const ControlChart chart = individualsChart(kLoanCosts);
    const ChartLimits& l = chart.limits;
    EXPECT_EQ(l.kind, ChartKind::IndividualsMovingRange);
    EXPECT_EQ(l.subgroupSize, 1);
    EXPECT_NEAR(l.location.centreMm, 300.5, 1e-12);
    EXPECT_NEAR(l.spread.centreMm, 148.0 / 19.0, 1e-12);
    EXPECT_NEAR(l.location.upperMm, 321.22, 0.01);
    EXPECT_NEAR(l.location.lowerMm, 279.78, 0.01);
    EXPECT_NEAR(l.spread.upperMm, 25.45, 0.01);
    EXPECT_EQ(l.spread.lowerMm, 0.0);
    EXPECT_NEAR(l.sigmaWithinMm, 148.0 / 19.0 / 1.128, 1e-12);
    ASSERT_EQ(chart.spreadMm.size(), 19u);
    EXPECT_EQ(chart.spreadFirstPoint, 1u);
    EXPECT_DOUBLE_EQ(chart.spreadMm[0], 22.0);  // |288 - 310|, plotted at the second point
    EXPECT_TRUE(chart.locationBeyondLimits.empty());
    EXPECT_TRUE(chart.spreadBeyondLimits.empty());
}

// Phase I on the first 10 weeks, held: the limits are those of the 10 values alone (moving ranges inside the
// baseline only); a later cost of 340 and the jump to it are flagged at their own points.
TEST(IndividualsChart, BaselineLimitsAreHeld) {
    std::vector<double> costs(kLoanCosts.begin(), kLoanCosts.end());
    costs.push_back(340.0);
    const ControlChart chart = individualsChart(costs, ChartBaseline{0, 10});
    const ChartLimits alone = individualsLimits(std::span<const double>(kLoanCosts).first(10));
    EXPECT_DOUBLE_EQ(chart.limits.location.upperMm, alone.location.upperMm);
    EXPECT_DOUBLE_EQ(chart.limits.spread.upperMm, alone.spread.upperMm);
    EXPECT_EQ(chart.locationBeyondLimits, std::vector<std::size_t>{20});
    EXPECT_EQ(chart.spreadBeyondLimits, std::vector<std::size_t>{20});
    const ControlChart held = individualsChart(costs, alone);
    EXPECT_EQ(held.locationBeyondLimits, chart.locationBeyondLimits);
}

TEST(IndividualsChart, BadInputIsRefused) {
    EXPECT_THROW(individualsChart(std::vector<double>{300.0}), std::invalid_argument);
    EXPECT_THROW(individualsChart(std::vector<double>(10, 300.0)), std::invalid_argument);
    EXPECT_THROW(individualsChart(kLoanCosts, ChartBaseline{19, 5}), std::invalid_argument);
    const ChartLimits xbar{ChartKind::XbarRange, 5, {}, {}, 1.0, 1.0, 0, 2};
    EXPECT_THROW(individualsChart(kLoanCosts, xbar), std::invalid_argument);
    ChartLimits reversed = individualsLimits(kLoanCosts);
    std::swap(reversed.location.lowerMm, reversed.location.upperMm);
    EXPECT_THROW(individualsChart(kLoanCosts, reversed), std::invalid_argument);
    ChartLimits noSigma = individualsLimits(kLoanCosts);
    noSigma.locationSigmaMm = 0.0;
    EXPECT_THROW(individualsChart(kLoanCosts, noSigma), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
