#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/quality/capability.h"
#include "core/quality/distributions.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

// NIST/SEMATECH e-Handbook, section 6.1.6 ("What is process capability?"), the worked example: USL = 20,
// LSL = 8, mu = 16, sigma = 2: Cp = 12/12 = 1, Cpk = min(4/6, 8/6) = 0.6667. Tolerance 5e-5 (the
// handbook's four decimals); Cp is exact.
TEST(Capability, HandbookSection616Example) {
    const CapabilityIndices c = normalCapabilityIndices({100, 16.0, 2.0, 2.0}, SpecLimits{8.0, 20.0, {}});
    EXPECT_NEAR(c.cp, 1.0, 1e-15);
    EXPECT_NEAR(c.cpk, 0.6667, 5e-5);
    EXPECT_NEAR(c.pp, 1.0, 1e-15);
    EXPECT_NEAR(c.ppk, 0.6667, 5e-5);
}

// Montgomery (2009), Example 8.4: USL = 62, LSL = 38, n = 20, s = 1.75: Cp = 2.29 and the 95 % interval
// 2.29 sqrt(8.91/19) <= Cp <= 2.29 sqrt(32.85/19), i.e. 1.57 .. 3.01. The book rounds Cp to 2.29 before
// multiplying (the unrounded 2.2857 gives 1.565 .. 3.006): tolerance 0.01.
TEST(Capability, MontgomeryExample84CpInterval) {
    const CapabilityIndices c = normalCapabilityIndices({20, 50.0, 1.75, 1.75}, SpecLimits{38.0, 62.0, {}});
    EXPECT_NEAR(c.cp, 2.29, 0.005);
    ASSERT_TRUE(c.cpInterval);
    EXPECT_NEAR(c.cpInterval->lower, 1.57, 0.01);
    EXPECT_NEAR(c.cpInterval->upper, 3.01, 0.01);
    // The interval is exactly Cp sqrt(chi2(alpha/2; 19)/19) .. Cp sqrt(chi2(1 - alpha/2; 19)/19).
    EXPECT_NEAR(c.cpInterval->lower, c.cp * std::sqrt(chiSquareQuantile(0.025, 19.0) / 19.0), 1e-12);
}

// Montgomery (2009), Example 8.5: n = 20, Cpk = 1.33; Bissell's approximate 95 % interval 1.33 -+ 1.96
// sqrt(1/(9 * 20) + 1.33^2/(2 * 19)) = 0.88 .. 1.78. The moments are chosen to give Cpk = 1.33 exactly
// (mean 50 in 0 .. 100, sigma 50/3.99). Tolerance 0.005 (two decimals).
TEST(Capability, MontgomeryExample85CpkInterval) {
    const double sigma = 50.0 / (3.0 * 1.33);
    const CapabilityIndices c = normalCapabilityIndices({20, 50.0, sigma, sigma}, SpecLimits{0.0, 100.0, {}});
    EXPECT_NEAR(c.cpk, 1.33, 1e-12);
    ASSERT_TRUE(c.cpkInterval);
    EXPECT_NEAR(c.cpkInterval->lower, 0.88, 0.005);
    EXPECT_NEAR(c.cpkInterval->upper, 1.78, 0.005);
}

// Montgomery (2009), Section 6.2 (process capability from the X-bar-R chart): the piston rings with
// specifications 74.000 +- 0.05 mm and sigma = R-bar/d2 = 0.0099 give Cp = 0.10/(6 * 0.0099) = 1.68. The book rounds
// sigma to 0.0099 (exactly 0.00999): tolerance 0.015. Cpm with the target in the middle, N = 125: Chan, Cheng &
// Spiring's formula by hand.
TEST(Capability, PistonRingsMatchMontgomerySection625) {
    CapabilitySettings settings;
    settings.within = WithinSigmaMethod::Range;
    settings.subgroupSize = 5;
    const CapabilityStudy s = capabilityStudy(test::kPistonRings, SpecLimits{73.95, 74.05, {}}, settings);
    EXPECT_EQ(s.count, 125u);
    EXPECT_NEAR(s.sigmaWithinMm, 0.0099, 0.0001);
    // The Anderson-Darling test does not reject the piston rings (our A^2; the same figure as statsmodels'
    // normal_ad, see scripts/crosscheck-quality.py), so the normal method is used.
    EXPECT_GT(s.normality.pValue, 0.05);
    ASSERT_EQ(s.method, CapabilityMethod::Normal);
    EXPECT_NEAR(s.indices.cp, 1.68, 0.015);
    EXPECT_FALSE(s.percentiles);
    ASSERT_TRUE(s.indices.cpm);
    double sumOfSquares = 0.0;
    for (const double x : test::kPistonRings)
        sumOfSquares += (x - 74.0) * (x - 74.0);
    EXPECT_NEAR(*s.indices.cpm, 0.1 / (6.0 * std::sqrt(sumOfSquares / 124.0)), 1e-9);
    EXPECT_TRUE(s.indices.cpInterval && s.indices.cpkInterval && s.indices.cpmInterval && s.indices.ppInterval &&
                s.indices.ppkInterval);
    EXPECT_EQ(s.belowLower + s.aboveUpper, 0u);
}

/// n exponential quantiles -ln(1 - (i - 0.5)/n): a clearly skewed, reproducible sample.
std::vector<double> exponentialSample(int n) {
    std::vector<double> v;
    for (int i = 1; i <= n; ++i)
        v.push_back(-std::log(1.0 - (i - 0.5) / n));
    return v;
}

// Normality rejected: the percentile method of ISO 22514-2, quantiles by Hyndman & Fan definition 7 worked
// out by hand here (h = (N - 1) p), Pp = (U - L)/(X99.865 - X0.135), Ppk = min((U - X50)/(X99.865 - X50),
// (X50 - L)/(X50 - X0.135)); Cp = Pp, Cpk = Ppk, no Cpm and no intervals. Exact up to rounding (1e-12).
TEST(Capability, PercentileMethodWhenNormalityIsRejected) {
    const std::vector<double> v = exponentialSample(200);
    const SpecLimits spec{0.0, 8.0, {}};
    const CapabilityStudy s = capabilityStudy(v, spec);
    ASSERT_EQ(s.method, CapabilityMethod::Percentile);
    EXPECT_LT(s.normality.pValue, 0.05);
    ASSERT_TRUE(s.percentiles);
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    const auto quantile = [&sorted](double p) {
        const double h = 199.0 * p;
        const auto i = static_cast<std::size_t>(h);
        return sorted[i] + (h - static_cast<double>(i)) * (sorted[i + 1] - sorted[i]);
    };
    const double low = quantile(0.00135), median = quantile(0.5), high = quantile(0.99865);
    EXPECT_NEAR(s.percentiles->lowerMm, low, 1e-12);
    EXPECT_NEAR(s.percentiles->medianMm, median, 1e-12);
    EXPECT_NEAR(s.percentiles->upperMm, high, 1e-12);
    EXPECT_NEAR(s.indices.pp, 8.0 / (high - low), 1e-12);
    EXPECT_NEAR(s.indices.ppk, std::min((8.0 - median) / (high - median), median / (median - low)), 1e-12);
    EXPECT_EQ(s.indices.cp, s.indices.pp);
    EXPECT_EQ(s.indices.cpk, s.indices.ppk);
    EXPECT_FALSE(s.indices.cpm);
    EXPECT_FALSE(s.indices.cpInterval);
    EXPECT_FALSE(s.indices.cpkInterval);

    // normalityAlpha = 0 never rejects: the normal indices of the same data.
    CapabilitySettings always;
    always.normalityAlpha = 0.0;
    EXPECT_EQ(capabilityStudy(v, spec, always).method, CapabilityMethod::Normal);
}

// Values outside the limits are counted (here 3 below and 2 above).
TEST(Capability, CountsValuesOutsideTheLimits) {
    const std::vector<double> v = {9.0, 9.5, 9.9, 10.0, 10.1, 10.2, 10.3, 10.4, 10.5, 11.0, 11.2, 9.8};
    const CapabilityStudy s = capabilityStudy(v, SpecLimits{9.85, 10.9, {}});
    EXPECT_EQ(s.belowLower, 3u);
    EXPECT_EQ(s.aboveUpper, 2u);
}

TEST(Capability, BadInputIsRefused) {
    const std::vector<double> v = exponentialSample(50);
    EXPECT_THROW(capabilityStudy(v, SpecLimits{2.0, 1.0, {}}), std::invalid_argument);
    EXPECT_THROW(capabilityStudy(v, SpecLimits{0.0, 1.0, 2.0}), std::invalid_argument);
    CapabilitySettings settings;
    settings.confidence = 1.0;
    EXPECT_THROW(capabilityStudy(v, SpecLimits{0.0, 8.0, {}}, settings), std::invalid_argument);
    settings.confidence = 0.95;
    settings.within = WithinSigmaMethod::Range;
    settings.subgroupSize = 30;
    EXPECT_THROW(capabilityStudy(v, SpecLimits{0.0, 8.0, {}}, settings), std::invalid_argument);
    EXPECT_THROW(capabilityStudy(std::vector<double>(5, 1.0), SpecLimits{0.0, 8.0, {}}), std::invalid_argument);
    EXPECT_THROW(capabilityStudy(std::vector<double>(50, 1.0), SpecLimits{0.0, 8.0, {}}), std::invalid_argument);
    EXPECT_THROW(normalCapabilityIndices({20, 1.0, 0.0, 1.0}, SpecLimits{0.0, 8.0, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
