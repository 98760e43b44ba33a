// The prediction-error ARMA fit (core/control/arma_identification.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/control/arma_identification.h"
#include "tests/core/support/arma_series.h"

namespace tt::core {
namespace {

// Issue 13: a simulated ARMA(1, 1) with a = 0.92, b = 0.25 and 2,000 parts; the fit recovers a and b
// within 0.03. sigma = 0.01 mm (the scale of the paper-2012 disturbance).
TEST(ArmaIdentification, RecoversArma11From2000Parts) {
    const std::vector<double> y = test::simulateArma11(0.92, 0.25, 0.01, 2000, 1);
    const ArmaFit fit = fitArma(y, {1, 1});
    ASSERT_EQ(fit.ar.size(), 1u);
    ASSERT_EQ(fit.ma.size(), 1u);
    EXPECT_NEAR(fit.ar[0], 0.92, 0.03);
    EXPECT_NEAR(fit.ma[0], 0.25, 0.03);
    // The innovation variance is sigma^2 = 1e-4 mm^2 within its sampling error (about 3 % at n = 2000).
    EXPECT_NEAR(fit.noiseVarianceMm2, 1e-4, 1e-5);
    // Residuals of the right model are white: the Ljung-Box p-value is not small.
    EXPECT_GT(fit.ljungBoxP, 0.01);
    EXPECT_EQ(fit.ljungBoxLags, 20);
}

// The same series fitted by statsmodels 0.13.5 (Debian 12 python3-statsmodels), ARIMA(1, 0, 1) with a
// constant, exact Gaussian likelihood: a = 0.91666, b = 0.26499, standard errors 0.00939 and 0.02299
// (scripts/crosscheck-arma.py, "engine test, seed 1"). Ours minimises the conditional sum of squares:
// the coefficients agree within 0.01 (O(1/n)), the standard errors within 15 %.
TEST(ArmaIdentification, AgreesWithStatsmodelsOnTheSameSeries) {
    const ArmaFit fit = fitArma(test::simulateArma11(0.92, 0.25, 0.01, 2000, 1), {1, 1});
    EXPECT_NEAR(fit.ar[0], 0.91666, 0.01);
    EXPECT_NEAR(fit.ma[0], 0.26499, 0.01);
    EXPECT_NEAR(fit.arStdErr[0], 0.00939, 0.15 * 0.00939);
    EXPECT_NEAR(fit.maStdErr[0], 0.02299, 0.15 * 0.02299);
}

// Over 40 independent series the estimates are unbiased within their standard error of the mean, and
// the reported standard errors match the scatter of the estimates (asymptotic theory: for ARMA(1, 1),
// var(b) = (1 + ab)^2 (1 - b^2) / (n (a + b)^2) = 0.0228^2 at n = 2000; Box, Jenkins & Reinsel, 4th ed., 7.3.5).
TEST(ArmaIdentification, StandardErrorsMatchTheScatterOfTheEstimates) {
    constexpr int kSeries = 40;
    std::vector<double> a, b;
    double seB = 0.0;
    for (int s = 0; s < kSeries; ++s) {
        const ArmaFit fit = fitArma(test::simulateArma11(0.92, 0.25, 0.01, 2000, 100 + s), {1, 1});
        a.push_back(fit.ar[0]);
        b.push_back(fit.ma[0]);
        seB += fit.maStdErr[0] / kSeries;
    }
    const auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); };
    const auto sd = [&](const std::vector<double>& v) {
        const double m = mean(v);
        double s = 0.0;
        for (double x : v)
            s += (x - m) * (x - m);
        return std::sqrt(s / (v.size() - 1));
    };
    EXPECT_NEAR(mean(a), 0.92, 0.01);
    EXPECT_NEAR(mean(b), 0.25, 0.015);
    EXPECT_NEAR(seB, 0.0228, 0.003);
    // The scatter of 40 estimates estimates the standard error within about 25 % (chi-square, 39 dof, 95 %).
    EXPECT_NEAR(sd(b) / seB, 1.0, 0.3);
}

// An AR(1) fitted as AR(1): the least-squares answer (no MA term) is the lag-1 autocorrelation regression.
TEST(ArmaIdentification, Ar1IsTheLeastSquaresRegression) {
    const std::vector<double> y = test::simulateArma11(0.7, 0.0, 1.0, 1000, 7);
    const ArmaFit fit = fitArma(y, {1, 0});
    const double mean = std::accumulate(y.begin(), y.end(), 0.0) / y.size();
    double num = 0.0, den = 0.0;
    for (std::size_t t = 1; t < y.size(); ++t) {
        num += (y[t] - mean) * (y[t - 1] - mean);
        den += (y[t - 1] - mean) * (y[t - 1] - mean);
    }
    // The conditional residual of the first value is y(0) itself, which the regression ignores: the two
    // answers differ by O(1/n).
    EXPECT_NEAR(fit.ar[0], num / den, 2e-3);
    EXPECT_TRUE(fit.ma.empty());
}

// A wrong model leaves correlated residuals: white noise fitted to an ARMA(1, 1) fails Ljung-Box.
TEST(ArmaIdentification, LjungBoxRejectsAnUnderfittedModel) {
    const ArmaFit fit = fitArma(test::simulateArma11(0.92, 0.25, 0.01, 2000, 3), {0, 0});
    EXPECT_LT(fit.ljungBoxP, 1e-6);
}

// The fit as the presets' shaping filter: W(z) = (z + b) / (z - a) with the noise variance as its input.
TEST(ArmaIdentification, OffersTheShapingFilter) {
    const ArmaFit fit = fitArma(test::simulateArma11(0.92, 0.25, 0.01, 2000, 1), {1, 1});
    const DisturbanceModel model = fit.disturbanceModel();
    const auto& filter = model.components().front().filter();
    ASSERT_TRUE(filter);
    EXPECT_DOUBLE_EQ(filter->numerator()[1], fit.ma[0]);
    EXPECT_DOUBLE_EQ(filter->denominator()[1], -fit.ar[0]);
    // Stationary variance of ARMA(1, 1): sigma^2 (1 + 2ab + b^2) / (1 - a^2).
    const double a = fit.ar[0], b = fit.ma[0];
    EXPECT_NEAR(model.stationaryVarianceMm2(), fit.noiseVarianceMm2 * (1 + 2 * a * b + b * b) / (1 - a * a),
                1e-9 * model.stationaryVarianceMm2());
}

TEST(ArmaIdentification, RefusesBadInput) {
    EXPECT_THROW(fitArma(std::vector<double>(49, 1.0), {1, 1}), std::invalid_argument);
    EXPECT_THROW(fitArma(std::vector<double>(100, 1.0), {1, 1}), std::invalid_argument);  // constant
    std::vector<double> y = test::simulateArma11(0.5, 0.0, 1.0, 100, 1);
    EXPECT_THROW(fitArma(y, {5, 0}), std::invalid_argument);
    y[10] = std::nan("");
    EXPECT_THROW(fitArma(y, {1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
