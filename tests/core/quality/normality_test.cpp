#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/quality/distributions.h"
#include "core/quality/normality.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

// D'Agostino & Stephens (1986), Goodness-of-Fit Techniques, Table 4.7, case 3 (normal, mean and variance
// estimated): upper-tail percentage points of A*^2 = A^2 (1 + 0.75/n + 2.25/n^2): 10 % 0.631, 5 % 0.752,
// 2.5 % 0.873, 1 % 1.035. The p-value formulas of Table 4.9 are a fit to those points: tolerance 0.001.
TEST(AndersonDarling, PValuesAtThePublishedCriticalValues) {
    EXPECT_NEAR(andersonDarlingPValue(0.631), 0.10, 0.001);
    EXPECT_NEAR(andersonDarlingPValue(0.752), 0.05, 0.001);
    EXPECT_NEAR(andersonDarlingPValue(0.873), 0.025, 0.001);
    EXPECT_NEAR(andersonDarlingPValue(1.035), 0.01, 0.001);
    // The four formulas join at 0.2, 0.34 and 0.6 (to within 0.005) and stay within 0..1.
    for (const double joint : {0.2, 0.34, 0.6})
        EXPECT_NEAR(andersonDarlingPValue(joint - 1e-9), andersonDarlingPValue(joint), 0.005) << joint;
    EXPECT_LE(andersonDarlingPValue(0.0), 1.0);
    EXPECT_GE(andersonDarlingPValue(0.0), 0.99);
    EXPECT_EQ(andersonDarlingPValue(13.5), 0.0);
    EXPECT_THROW(andersonDarlingPValue(-0.1), std::invalid_argument);
}

/// n values at the normal scores Phi^-1((i - 0.375)/(n + 0.25)) (Blom 1958), scaled to mean m, sigma s.
std::vector<double> normalScores(std::size_t n, double m, double s) {
    std::vector<double> v;
    for (std::size_t i = 1; i <= n; ++i)
        v.push_back(m + s * normalQuantile((static_cast<double>(i) - 0.375) / (static_cast<double>(n) + 0.25)));
    return v;
}

// Values at the expected normal order statistics fit a normal distribution almost perfectly: A^2 is
// tiny and p close to 1 (not a published figure: a property of the statistic); an exponential sample
// (quantiles -ln(1 - (i - 0.5)/n)) is rejected far below 1 %.
TEST(AndersonDarling, AcceptsNormalScoresAndRejectsAnExponentialSample) {
    const NormalityTest normal = andersonDarlingNormality(normalScores(100, 20.0, 0.01));
    EXPECT_EQ(normal.count, 100u);
    EXPECT_LT(normal.a2, 0.05);
    EXPECT_GT(normal.pValue, 0.99);
    std::vector<double> exponential;
    for (int i = 1; i <= 100; ++i)
        exponential.push_back(-std::log(1.0 - (i - 0.5) / 100.0));
    const NormalityTest skewed = andersonDarlingNormality(exponential);
    EXPECT_GT(skewed.a2Adjusted, 2.0);
    EXPECT_LT(skewed.pValue, 0.001);
    EXPECT_NEAR(skewed.a2Adjusted, skewed.a2 * (1.0 + 0.75 / 100.0 + 2.25 / 1e4), 1e-12);
}

// A^2 does not change when the values are shifted, scaled or reordered (relative 1e-12): it depends only
// on the standardised order statistics. The piston rings of Montgomery Table 6.3 as the data.
TEST(AndersonDarling, InvariantUnderShiftScaleAndOrder) {
    const NormalityTest base = andersonDarlingNormality(test::kPistonRings);
    std::vector<double> changed;
    for (const double x : test::kPistonRings)
        changed.push_back(1000.0 * (x - 74.0) + 5.0);
    std::reverse(changed.begin(), changed.end());
    const NormalityTest other = andersonDarlingNormality(changed);
    EXPECT_NEAR(other.a2 / base.a2, 1.0, 1e-9);
    EXPECT_NEAR(other.pValue, base.pValue, 1e-9);
}

// A gross outlier (z of about 30 among 1000 values) keeps every figure finite; p is 0.
TEST(AndersonDarling, GrossOutlierStaysFinite) {
    std::vector<double> v = normalScores(999, 0.0, 1.0);
    v.push_back(1.0e3);
    const NormalityTest t = andersonDarlingNormality(v);
    EXPECT_TRUE(std::isfinite(t.a2));
    EXPECT_GT(t.a2Adjusted, 13.0);
    EXPECT_EQ(t.pValue, 0.0);
}

TEST(AndersonDarling, BadInputIsRefused) {
    EXPECT_THROW(andersonDarlingNormality(std::vector<double>(7, 1.0)), std::invalid_argument);
    EXPECT_THROW(andersonDarlingNormality(std::vector<double>(20, 1.0)), std::invalid_argument);
    std::vector<double> v = normalScores(20, 0.0, 1.0);
    v[3] = std::numeric_limits<double>::infinity();
    EXPECT_THROW(andersonDarlingNormality(v), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
