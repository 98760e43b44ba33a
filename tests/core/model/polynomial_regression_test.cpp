#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/polynomial_regression.h"
#include "core/model/systematic_error_model.h"

namespace tt::core {
namespace {

Eigen::VectorXd vec(const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

double relativeError(double actual, double expected) {
    return std::abs(actual - expected) / std::abs(expected);
}

// ---------------------------------------------------------------------------------------------
// Paper 000, Table 1 (shared/SEEDS.md, section 000): d(x) = b0 + ... + b5 x^5, x in mm, d in mm.
struct TableOneGroup {
    int group;
    std::vector<double> b;
    double peakMm;  // largest d on 0..325 mm (SEEDS.md: about 0.156, 0.104, 0.206 near x = 140 mm)
};
const std::vector<TableOneGroup> kTableOne = {
    {1, {0.071, -0.000132, 2.379e-5, -2.09e-7, 6.42e-10, -6.6e-13}, 0.156},
    {2, {-0.0019, 0.00039, 1.96e-5, -1.98e-7, 6.47e-10, -7.07e-13}, 0.104},
    {3, {0.064, 0.0016, 2.34e-6, -7.34e-8, 2.17e-10, -1.73e-13}, 0.206},
};

/// Exact samples of sum b_k x^k (long double Horner), every `stepMm` from 0 to `lengthMm`.
std::pair<Eigen::VectorXd, Eigen::VectorXd> sample(const std::vector<double>& b, double lengthMm, double stepMm) {
    std::vector<double> x, y;
    for (double xi = 0.0; xi <= lengthMm + 1e-9; xi += stepMm) {
        long double sum = 0.0L;
        for (std::size_t k = b.size(); k-- > 0;)
            sum = sum * static_cast<long double>(xi) + static_cast<long double>(b[k]);
        x.push_back(xi);
        y.push_back(static_cast<double>(sum));
    }
    return {vec(x), vec(y)};
}

TEST(TableOne, RegressionRecoversTheCoefficientsOfEveryGroup) {
    for (const TableOneGroup& g : kTableOne) {
        // 14 points every 25 mm on the 325 mm shaft, as the paper's parts were gauged.
        const auto [x, y] = sample(g.b, 325.0, 25.0);
        ASSERT_EQ(x.size(), 14);
        const PolynomialRegression fit = fitPolynomialRegression(x, y, 5);
        ASSERT_EQ(fit.coefficients.size(), 6);
        for (int k = 0; k <= 5; ++k)
            EXPECT_LT(relativeError(fit.coefficients(k), g.b[static_cast<std::size_t>(k)]), 1e-9)
                << "group " << g.group << " b" << k << " = " << fit.coefficients(k);
        EXPECT_NEAR(fit.r2, 1.0, 1e-12);
        EXPECT_LT(fit.residualSigma, 1e-12);
    }
}

TEST(TableOne, ModelPeaksNearTheMiddleOfTheShaft) {
    for (const TableOneGroup& g : kTableOne) {
        const auto [x, y] = sample(g.b, 325.0, 25.0);
        const SystematicErrorModel model(fitPolynomialRegression(x, y, 5).polynomial, 325.0);
        const PolynomialPeak peak = model.peak();
        EXPECT_NEAR(peak.value, g.peakMm, 1e-3) << "group " << g.group;
        EXPECT_NEAR(peak.x, 140.0, 3.0) << "group " << g.group;
        // A stationary point: d'(x) = 0 there, and no sample of the shaft exceeds it.
        EXPECT_NEAR(model.diameterError().derivative(peak.x), 0.0, 1e-12);
        for (double xi = 0.0; xi <= 325.0; xi += 0.25)
            EXPECT_LE(std::abs(model.diameterErrorMm(xi)), std::abs(peak.value) + 1e-15);
        EXPECT_DOUBLE_EQ(model.feedForwardMm(peak.x), -peak.value / 2.0);
    }
}

TEST(TableOne, StaysAccurateForAShaftMetresLong) {
    // The group 1 profile stretched to a 3.25 m shaft: b_k' = b_k / 10^k (x in mm up to 3250).
    std::vector<double> b = kTableOne[0].b;
    for (std::size_t k = 0; k < b.size(); ++k)
        b[k] /= std::pow(10.0, static_cast<double>(k));
    const auto [x, y] = sample(b, 3250.0, 50.0);
    const PolynomialRegression fit = fitPolynomialRegression(x, y, 5);
    for (int k = 0; k <= 5; ++k)
        EXPECT_LT(relativeError(fit.coefficients(k), b[static_cast<std::size_t>(k)]), 1e-9) << "b" << k;
}

TEST(TableOne, AutomaticDegreeFindsTheFifthDegree) {
    for (const TableOneGroup& g : kTableOne) {
        const auto [x, y] = sample(g.b, 325.0, 25.0);
        const DegreeSelection s = fitPolynomialRegressionAutoDegree(x, y);
        EXPECT_EQ(s.fit.degree, 5) << "group " << g.group;
        ASSERT_EQ(s.candidates.size(), 6U);
        EXPECT_GT(s.candidates[3].press, 1e-9) << "degree 4 cannot follow the fifth-degree profile";
    }
}

// ---------------------------------------------------------------------------------------------
// NIST Statistical Reference Datasets, linear least squares, "Wampler1", "Wampler4", "Wampler5"
// (https://www.itl.nist.gov/div898/strd/lls/data/Wampler1.shtml etc.): degree-5 polynomials in
// x = 0..20. Certified values copied from the NIST pages.
const std::vector<double> kWamplerX = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};

TEST(NistWampler, Wampler1ExactFitHasUnitCoefficients) {
    const std::vector<double> y = {1,      6,      63,      364,     1365,    3906,    9331,
                                   19608,  37449,  66430,   111111,  177156,  271453,  402234,
                                   579195, 813616, 1118481, 1508598, 2000719, 2613660, 3368421};
    const PolynomialRegression fit = fitPolynomialRegression(vec(kWamplerX), vec(y), 5);
    for (int k = 0; k <= 5; ++k)
        EXPECT_NEAR(fit.coefficients(k), 1.0, 1e-9) << "b" << k;  // certified: 1, standard deviation 0
    EXPECT_NEAR(fit.r2, 1.0, 1e-15);                              // certified R-squared 1
    EXPECT_LT(fit.residualSigma, 1e-8);                           // certified residual SD 0
}

TEST(NistWampler, Wampler4CertifiedStatistics) {
    const std::vector<double> y = {75901,   -204794, 204863,  -204436, 253665,  -200894, 214131,
                                   -185192, 221249,  -138370, 315911,  -27644,  455253,  197434,
                                   783995,  608816,  1370781, 1303798, 2205519, 2408860, 3444321};
    const PolynomialRegression fit = fitPolynomialRegression(vec(kWamplerX), vec(y), 5);
    const std::vector<double> se = {215232.624678170, 236355.173469681, 77934.3524331583,
                                    10147.5507550350, 564.566512170752, 11.2324854679312};
    for (int k = 0; k <= 5; ++k) {
        EXPECT_NEAR(fit.coefficients(k), 1.0, 1e-8) << "b" << k;
        EXPECT_LT(relativeError(fit.coefficientStdErrors(k), se[static_cast<std::size_t>(k)]), 1e-9) << "se b" << k;
    }
    EXPECT_LT(relativeError(fit.residualSigma, 236014.502379268), 1e-10);
    EXPECT_LT(relativeError(fit.r2, 0.957478440825662), 1e-12);
    EXPECT_LT(relativeError(fit.fStatistic, 67.5524458240122), 1e-9);
    EXPECT_LT(relativeError(fit.residualSumOfSquares, 835542680000.000), 1e-10);
    EXPECT_EQ(fit.residualDof, 15);
    // Adjusted R^2 is not certified; by hand from the certified R^2: 1 - (1 - R^2) * 20 / 15.
    EXPECT_NEAR(fit.r2Adjusted, 1.0 - (1.0 - 0.957478440825662) * 20.0 / 15.0, 1e-12);
    // F(0.95; 5, 15) = 2.901 (F distribution table, NIST/SEMATECH e-Handbook of Statistical
    // Methods, section 1.3.6.7.3, upper 5 % points).
    EXPECT_NEAR(fit.fCritical95, 2.901, 5e-4);
}

TEST(NistWampler, Wampler5TinyRSquared) {
    const std::vector<double> y = {7590001,   -20479994, 20480063,  -20479636, 25231365,  -20476094, 20489331,
                                   -20460392, 18417449,  -20413570, 20591111,  -20302844, 18651453,  -20077766,
                                   21059195,  -19666384, 26348481,  -18971402, 22480719,  -17866340, 10958421};
    const PolynomialRegression fit = fitPolynomialRegression(vec(kWamplerX), vec(y), 5);
    const std::vector<double> se = {21523262.4678170, 23635517.3469681, 7793435.24331583,
                                    1014755.07550350, 56456.6512170752, 1123.24854679312};
    for (int k = 0; k <= 5; ++k) {
        EXPECT_NEAR(fit.coefficients(k), 1.0, 1e-6) << "b" << k;
        EXPECT_LT(relativeError(fit.coefficientStdErrors(k), se[static_cast<std::size_t>(k)]), 1e-9) << "se b" << k;
    }
    EXPECT_LT(relativeError(fit.residualSigma, 23601450.2379268), 1e-10);
    EXPECT_LT(relativeError(fit.r2, 0.224668921574940e-2), 1e-8);
    EXPECT_LT(relativeError(fit.fStatistic, 6.7552445824012241e-3), 1e-8);
}

// ---------------------------------------------------------------------------------------------
// A straight line through five points, computed by hand with the textbook formulas
// (b1 = Sxy/Sxx, b0 = ybar - b1 xbar, s^2 = SSE/(n-2), se(b1) = s/sqrt(Sxx),
// se(b0) = s sqrt(1/n + xbar^2/Sxx), bands t s sqrt(h) and t s sqrt(1 + h), h = 1/n + (x-xbar)^2/Sxx):
// x = 1..5, y = {1, 3, 2, 5, 4}: xbar = ybar = 3, Sxx = 10, Sxy = 8, b1 = 0.8, b0 = 0.6,
// residuals {-0.4, 0.8, -1, 1.2, -0.6}, SSE = 3.6, SST = 10, s^2 = 1.2, R^2 = 0.64,
// adjusted R^2 = 0.52, F = 6.4 / 1.2 = 16/3, se(b1) = sqrt(0.12), se(b0) = sqrt(1.32),
// leverages {0.6, 0.3, 0.2, 0.3, 0.6}, PRESS = 1 + (8/7)^2 + 1.25^2 + (12/7)^2 + 1.5^2.
const std::vector<double> kLineX = {1, 2, 3, 4, 5};
const std::vector<double> kLineY = {1, 3, 2, 5, 4};

TEST(HandComputedLine, CoefficientsAndStatistics) {
    const PolynomialRegression fit = fitPolynomialRegression(vec(kLineX), vec(kLineY), 1);
    EXPECT_NEAR(fit.coefficients(0), 0.6, 1e-14);
    EXPECT_NEAR(fit.coefficients(1), 0.8, 1e-14);
    EXPECT_NEAR(fit.residualSumOfSquares, 3.6, 1e-13);
    EXPECT_NEAR(fit.totalSumOfSquares, 10.0, 1e-13);
    EXPECT_NEAR(fit.r2, 0.64, 1e-14);
    EXPECT_NEAR(fit.r2Adjusted, 0.52, 1e-14);
    EXPECT_NEAR(fit.fStatistic, 16.0 / 3.0, 1e-13);
    EXPECT_NEAR(fit.residualSigma, std::sqrt(1.2), 1e-14);
    EXPECT_NEAR(fit.coefficientStdErrors(1), std::sqrt(0.12), 1e-14);
    EXPECT_NEAR(fit.coefficientStdErrors(0), std::sqrt(1.32), 1e-14);
    EXPECT_NEAR(fit.press, 1.0 + 64.0 / 49.0 + 1.5625 + 144.0 / 49.0 + 2.25, 1e-13);
    // F(0.95; 1, 3) = 10.13 (upper 5 % points of the F distribution, NIST/SEMATECH e-Handbook 1.3.6.7.3).
    EXPECT_NEAR(fit.fCritical95, 10.128, 1e-3);
}

TEST(HandComputedLine, ConfidenceAndPredictionBands) {
    const PolynomialRegression fit = fitPolynomialRegression(vec(kLineX), vec(kLineY), 1);
    // At x = 6: yhat = 5.4, h = 1/5 + 9/10 = 1.1; t(0.975; 3) = 3.182446305284263 (Student t table: 3.182).
    const double t = 3.182446305284263;
    const RegressionPrediction p = fit.predict(6.0);
    EXPECT_NEAR(p.value, 5.4, 1e-13);
    EXPECT_NEAR(p.confidenceHalfWidth, t * std::sqrt(1.2 * 1.1), 1e-9);
    EXPECT_NEAR(p.predictionHalfWidth, t * std::sqrt(1.2 * 2.1), 1e-9);
    // At the mean x the mean is known best: h = 1/5.
    EXPECT_NEAR(fit.predict(3.0).confidenceHalfWidth, t * std::sqrt(1.2 * 0.2), 1e-9);
    EXPECT_THROW(fit.predict(3.0, 1.0), std::invalid_argument);
}

TEST(Regression, PressEqualsBruteForceLeaveOneOut) {
    // PRESS from the hat matrix must equal refitting without each point in turn.
    const auto [x, y] = sample(kTableOne[1].b, 325.0, 25.0);
    Eigen::VectorXd noisy = y;
    const std::vector<double> noise = {0.004, -0.003, 0.001, 0.006, -0.005, 0.002,  -0.001,
                                       0.003, -0.006, 0.000, 0.005, -0.002, -0.004, 0.003};
    for (Eigen::Index i = 0; i < noisy.size(); ++i)
        noisy(i) += noise[static_cast<std::size_t>(i)];
    const PolynomialRegression fit = fitPolynomialRegression(x, noisy, 3);
    double press = 0.0;
    for (Eigen::Index leave = 0; leave < x.size(); ++leave) {
        Eigen::VectorXd xs(x.size() - 1), ys(x.size() - 1);
        for (Eigen::Index i = 0, j = 0; i < x.size(); ++i)
            if (i != leave) {
                xs(j) = x(i);
                ys(j++) = noisy(i);
            }
        press += std::pow(noisy(leave) - fitPolynomialRegression(xs, ys, 3).polynomial(x(leave)), 2);
    }
    EXPECT_LT(relativeError(fit.press, press), 1e-10);
}

TEST(Regression, AutomaticDegreePicksTheQuadraticUnderNoise) {
    // A quadratic profile with a fixed +-0.003 mm scatter (fixed in the test so it is reproducible):
    // leave-one-out picks 2, a straight line misses the curvature, higher degrees fit the noise.
    std::vector<double> x, y;
    const std::vector<double> noise = {0.0021,  -0.0013, 0.0004,  -0.0028, 0.0017,  0.0009, -0.0022, 0.0012,  -0.0005,
                                       0.0026,  -0.0017, -0.0008, 0.0019,  -0.0024, 0.0003, 0.0015,  -0.0011, 0.0027,
                                       -0.0019, 0.0006,  -0.0003, -0.0026, 0.0010,  0.0018, -0.0015, 0.0023,  -0.0007};
    for (std::size_t i = 0; i < noise.size(); ++i) {
        const double xi = 12.5 * static_cast<double>(i);
        x.push_back(xi);
        y.push_back(0.02 + 8e-4 * xi - 2.4e-6 * xi * xi + noise[i]);
    }
    const DegreeSelection s = fitPolynomialRegressionAutoDegree(vec(x), vec(y));
    EXPECT_EQ(s.fit.degree, 2);
    EXPECT_GT(s.candidates[0].press, s.candidates[1].press);
    EXPECT_GT(s.fit.fStatistic, s.fit.fCritical95);
}

TEST(Regression, AutomaticDegreeSkipsDegreesTheDataCannotCarry) {
    // Five points: degrees 4..6 need 6..8 points and are reported as not estimable.
    const DegreeSelection s = fitPolynomialRegressionAutoDegree(vec(kLineX), vec(kLineY));
    ASSERT_EQ(s.candidates.size(), 6U);
    for (std::size_t d = 3; d < 6; ++d)
        EXPECT_TRUE(std::isinf(s.candidates[d].press)) << "degree " << d + 1;
    EXPECT_EQ(s.fit.degree, 1);
}

TEST(Regression, RepeatedMeasurementsAtTheSamePositionsAreUsed) {
    // Three parts gauged at the same 14 positions (the paper's experiment): 42 rows, 14 distinct x.
    const auto [x, y] = sample(kTableOne[2].b, 325.0, 25.0);
    Eigen::VectorXd xs(42), ys(42);
    for (int part = 0; part < 3; ++part) {
        xs.segment(part * 14, 14) = x;
        ys.segment(part * 14, 14) = y.array() + 0.01 * (part - 1);
    }
    const PolynomialRegression fit = fitPolynomialRegression(xs, ys, 5);
    EXPECT_EQ(fit.pointCount, 42);
    EXPECT_LT(relativeError(fit.coefficients(5), kTableOne[2].b[5]), 1e-9);
    // Residuals are exactly +-0.01 (and 0): s^2 = 28 * 1e-4 / 36.
    EXPECT_NEAR(fit.residualSigma, std::sqrt(28e-4 / 36.0), 1e-12);
}

void expectRefused(const std::vector<double>& x, const std::vector<double>& y, int degree, const std::string& phrase) {
    try {
        fitPolynomialRegression(vec(x), vec(y), degree);
        FAIL() << "expected a refusal mentioning '" << phrase << "'";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
}

TEST(Regression, BadDataAreRefusedWithAReason) {
    expectRefused({0, 25, 50, 75, 100}, {0.1, 0.2, 0.15, 0.3, 0.2}, 4, "needs at least 6 points");
    expectRefused({0, 0, 25, 25, 50, 50, 50}, {0.1, 0.2, 0.15, 0.3, 0.2, 0.1, 0.3}, 3, "4 different x positions");
    expectRefused({10, 10, 10, 10}, {0.1, 0.2, 0.15, 0.3}, 1, "same position");
    expectRefused({0, 25, 50, 75}, {0.1, 0.1, 0.1, 0.1}, 1, "all values are equal");
    expectRefused({0, 25, 50, 75}, {0.1, std::nan(""), 0.1, 0.2}, 1, "data point 2");
    expectRefused({0, 25, 50}, {0.1, 0.2}, 1, "as many values");
    expectRefused({0, 25, 50, 75, 100, 125, 150, 175, 200}, {1, 2, 3, 4, 5, 6, 7, 8, 0}, 7, "1 .. 6");
    EXPECT_THROW(fitPolynomialRegressionAutoDegree(vec({0, 25}), vec({0.1, 0.2})), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
