#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/quality/distributions.h"

namespace tt::core {
namespace {

// Standard normal quantiles to 10 decimals (Abramowitz & Stegun, Table 26.5; the familiar 1.959964 of a
// 95 % two-sided interval): tolerance 1e-9.
TEST(Distributions, NormalQuantilesMatchTheTables) {
    EXPECT_NEAR(normalQuantile(0.975), 1.9599639845, 1e-9);
    EXPECT_NEAR(normalQuantile(0.995), 2.5758293035, 1e-9);
    // Phi(3) = 0.99865010197 (A&S Table 26.1): the 99.865 % point of ISO 22514-2 is 3 sigma.
    EXPECT_NEAR(normalCdf(3.0), 0.99865010197, 1e-10);
    EXPECT_NEAR(normalQuantile(normalCdf(3.0)), 3.0, 1e-10);
    EXPECT_NEAR(normalQuantile(0.5), 0.0, 1e-15);
    EXPECT_NEAR(normalQuantile(0.025), -normalQuantile(0.975), 1e-12);
    EXPECT_THROW(normalQuantile(0.0), std::invalid_argument);
    EXPECT_THROW(normalQuantile(1.0), std::invalid_argument);
}

// Chi-square percentage points (Montgomery, Introduction to SQC, Appendix III, two decimals): 19 degrees of
// freedom, lower tail 0.025 -> 8.91, 0.975 -> 32.85; 1 degree: 0.95 -> 3.84 (= 1.959964^2 exactly).
// Tolerance 0.005 (the table's rounding); the last one to 1e-10.
TEST(Distributions, ChiSquareQuantilesMatchTheTable) {
    EXPECT_NEAR(chiSquareQuantile(0.025, 19.0), 8.91, 0.005);
    EXPECT_NEAR(chiSquareQuantile(0.975, 19.0), 32.85, 0.005);
    EXPECT_NEAR(chiSquareQuantile(0.95, 1.0), std::pow(normalQuantile(0.975), 2), 1e-10);
    EXPECT_THROW(chiSquareQuantile(0.5, 0.0), std::invalid_argument);
    EXPECT_THROW(chiSquareQuantile(1.0, 5.0), std::invalid_argument);
}

// ln Phi(z): the Boost branch and the asymptotic series agree where they meet (z = -30, relative 1e-12), the
// series stays finite far out (z = -1000: A&S 26.2.12 with its first terms, -z^2/2 - ln(-z) - ln(2 pi)/2 +
// ln(1 - 1/z^2 + 3/z^4)), and the upper branch keeps precision near 0.
TEST(Distributions, LogNormalCdfIsAccurateInBothTails) {
    EXPECT_NEAR(logNormalCdf(0.0), std::log(0.5), 1e-15);
    EXPECT_NEAR(logNormalCdf(-29.999999), logNormalCdf(-30.000001), 1e-4);  // continuous across the switch
    const double atSwitch = std::log(normalCdf(-30.0));
    const double series = logNormalCdf(-30.0 - 1e-12);
    EXPECT_NEAR(series / atSwitch, 1.0, 1e-12);
    const double far = logNormalCdf(-1000.0);
    EXPECT_TRUE(std::isfinite(far));
    const double expected =
        -0.5e6 - std::log(1000.0) - 0.5 * std::log(2.0 * std::numbers::pi) + std::log1p(-1e-6 + 3e-12);
    EXPECT_NEAR(far / expected, 1.0, 1e-15);
    // ln Phi(10) = ln(1 - 7.62e-24) = -7.62e-24 (Phi(-10) = 7.6198530241605e-24, A&S 26.2.12).
    EXPECT_NEAR(logNormalCdf(10.0) / -7.6198530241605e-24, 1.0, 1e-10);
}

// Hyndman & Fan definition 7 on 1..5 (by hand: h = 4p): p = 0 -> 1, 0.5 -> 3, 0.1 -> 1.4, 0.99865 ->
// 4.9946, 1 -> 5; one value -> that value. Exact up to rounding (1e-12).
TEST(Distributions, EmpiricalQuantileIsDefinitionSeven) {
    const std::vector<double> v = {1.0, 2.0, 3.0, 4.0, 5.0};
    EXPECT_DOUBLE_EQ(empiricalQuantile(v, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(empiricalQuantile(v, 0.5), 3.0);
    EXPECT_NEAR(empiricalQuantile(v, 0.1), 1.4, 1e-12);
    EXPECT_NEAR(empiricalQuantile(v, 0.99865), 4.9946, 1e-12);
    EXPECT_DOUBLE_EQ(empiricalQuantile(v, 1.0), 5.0);
    EXPECT_DOUBLE_EQ(empiricalQuantile(std::vector<double>{7.0}, 0.3), 7.0);
    EXPECT_THROW(empiricalQuantile(std::vector<double>{}, 0.5), std::invalid_argument);
    EXPECT_THROW(empiricalQuantile(v, 1.5), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
