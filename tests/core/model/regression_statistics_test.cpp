// The regression statistics the force-deformation model is judged by (paper 004): least squares of
// several terms with R², adjusted R², F against its table value, standard errors and t-values, the
// residual sigma, and the stepwise removal of insignificant terms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/model/deformation_model.h"
#include "core/model/polynomial_regression.h"

namespace tt::core {
namespace {

double relativeError(double actual, double expected) {
    return std::abs(actual - expected) / std::abs(expected);
}

// ---------------------------------------------------------------------------------------------
// NIST Statistical Reference Datasets, linear least squares, "Longley" (higher difficulty; Longley,
// J. W. (1967), JASA 62, 819-841): 16 observations, 6 predictors. Data and certified values copied
// from https://www.itl.nist.gov/div898/strd/lls/data/Longley.shtml.
const double kLongley[16][7] = {
    {60323, 83.0, 234289, 2356, 1590, 107608, 1947},  {61122, 88.5, 259426, 2325, 1456, 108632, 1948},
    {60171, 88.2, 258054, 3682, 1616, 109773, 1949},  {61187, 89.5, 284599, 3351, 1650, 110929, 1950},
    {63221, 96.2, 328975, 2099, 3099, 112075, 1951},  {63639, 98.1, 346999, 1932, 3594, 113270, 1952},
    {64989, 99.0, 365385, 1870, 3547, 115094, 1953},  {63761, 100.0, 363112, 3578, 3350, 116219, 1954},
    {66019, 101.2, 397469, 2904, 3048, 117388, 1955}, {67857, 104.6, 419180, 2822, 2857, 118734, 1956},
    {68169, 108.4, 442769, 2936, 2798, 120445, 1957}, {66513, 110.8, 444546, 4681, 2637, 121950, 1958},
    {68655, 112.6, 482704, 3813, 2552, 123366, 1959}, {69564, 114.2, 502601, 3931, 2514, 125368, 1960},
    {69331, 115.7, 518173, 4806, 2572, 127852, 1961}, {70551, 116.9, 554894, 4007, 2827, 130081, 1962},
};

TEST(LinearRegression, LongleyCertifiedValues) {
    Eigen::MatrixXd x(16, 7);
    Eigen::VectorXd y(16);
    for (int i = 0; i < 16; ++i) {
        y(i) = kLongley[i][0];
        x(i, 0) = 1.0;
        for (int k = 1; k < 7; ++k)
            x(i, k) = kLongley[i][k];
    }
    const LinearRegression fit = fitLinearRegression(x, y);
    const double b[7] = {-3482258.63459582, 15.0618722713733,       -0.358191792925910E-01, -2.02022980381683,
                         -1.03322686717359, -0.511041056535807E-01, 1829.15146461355};
    const double se[7] = {890420.383607373,  84.9149257747669,  0.334910077722432E-01, 0.488399681651699,
                          0.214274163161675, 0.226073200069370, 455.478499142212};
    // Longley's columns span five orders of magnitude unscaled; QR keeps about 8 of NIST's 15 digits
    // (the normal equations would keep almost none).
    for (int k = 0; k < 7; ++k) {
        EXPECT_LT(relativeError(fit.coefficients(k), b[k]), 1e-7) << "B" << k;
        EXPECT_LT(relativeError(fit.coefficientStdErrors(k), se[k]), 1e-7) << "SE B" << k;
        EXPECT_NEAR(fit.tValues(k), b[k] / se[k], 1e-6 * std::abs(b[k] / se[k])) << "t B" << k;
    }
    EXPECT_LT(relativeError(fit.residualSigma, 304.854073561965), 1e-8);
    EXPECT_LT(relativeError(fit.r2, 0.995479004577296), 1e-10);
    EXPECT_LT(relativeError(fit.residualSumOfSquares, 836424.055505915), 1e-7);
    EXPECT_LT(relativeError(fit.totalSumOfSquares - fit.residualSumOfSquares, 184172401.944494), 1e-8);
    EXPECT_LT(relativeError(fit.fStatistic, 330.285339234588), 1e-7);
    EXPECT_EQ(fit.residualDof, 9);
    EXPECT_EQ(fit.termCount, 7);
    // Not certified; by hand from the certified R²: 1 - (1 - R²) (n - 1) / (n - p) = 1 - (1 - R²) 15 / 9.
    EXPECT_NEAR(fit.r2Adjusted, 1.0 - (1.0 - 0.995479004577296) * 15.0 / 9.0, 1e-10);
    // F(0.95; 6, 9) = 3.374 and t(0.975; 9) = 2.262 (NIST/SEMATECH e-Handbook of Statistical Methods,
    // tables 1.3.6.7.3 and 1.3.6.7.2).
    EXPECT_NEAR(fit.fCritical95, 3.374, 5e-4);
    EXPECT_NEAR(fit.tCritical95, 2.262, 5e-4);
}

TEST(LinearRegression, RefusesWhatCannotBeFitted) {
    Eigen::MatrixXd x(4, 3);
    x << 1, 0, 0, 1, 1, 2, 1, 2, 4, 1, 3, 6;  // column 3 = 2 x column 2
    const Eigen::VectorXd y = Eigen::Vector4d(1, 2, 4, 3);
    try {
        fitLinearRegression(x, y);
        FAIL() << "dependent columns were accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("term 3 of 3"), std::string::npos) << e.what();
    }
    EXPECT_THROW(fitLinearRegression(x.topRows(3), y.head(3)), std::invalid_argument);  // 3 terms need 4 points
    Eigen::MatrixXd noIntercept = x;
    noIntercept(0, 0) = 2.0;
    EXPECT_THROW(fitLinearRegression(noIntercept, y), std::invalid_argument);
    Eigen::VectorXd bad = y;
    bad(2) = std::nan("");
    EXPECT_THROW(fitLinearRegression(x.leftCols(2), bad), std::invalid_argument);
    EXPECT_THROW(fitLinearRegression(x.leftCols(2), Eigen::Vector4d::Constant(5.0)), std::invalid_argument);
    EXPECT_THROW(fitLinearRegression(x.leftCols(2), y.head(3)), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// A hand-checked example: a 2^3 factorial in a = 0.5 / 1.5 mm, f = 0.1 / 0.3 mm/rev, z = 100 / 300 mm
// with one centre point (1.0, 0.2, 200), coded to -1 / 0 / +1. The design is orthogonal, so by hand
// (Montgomery, Design and Analysis of Experiments, ch. 6): b0 = sum(y) / 9, b_k = sum(x_k y) / 8,
// SSE = sum(y^2) - 9 b0^2 - 8 sum(b_k^2), s^2 = SSE / (9 - 4), SE(b0) = s / 3, SE(b_k) = s / sqrt(8).
// y (µm), corners in standard order (a fastest), then the centre: 10 16 13 20 11 16 13 21 | 15.
//   sum y = 135 -> b0 = 15;  b_a = 26/8 = 3.25;  b_f = 14/8 = 1.75;  b_z = 2/8 = 0.25
//   sum y^2 = 2137, 9 b0^2 = 2025 -> SST = 112;  SSE = 112 - 8 (3.25^2 + 1.75^2 + 0.25^2) = 2.5
//   s^2 = 0.5, s = 0.70711;  SE(b0) = 0.23570, SE(b_k) = 0.25;  t = 13, 7, 1
//   R^2 = 1 - 2.5/112 = 0.977679;  adjusted = 1 - (2.5/5)/(112/8) = 0.964286;  F = (109.5/3)/0.5 = 73
//   table values: F(0.95; 3, 5) = 5.41, t(0.975; 5) = 2.571.
// Stepwise: |t(z)| = 1 < 2.571, so z goes; refit: SSE = 2.5 + 8 (0.25^2) = 3, s^2 = 3/6 = 0.5, SE(b_k)
// = 0.25, t = 13, 7; R^2 = 1 - 3/112 = 0.973214; adjusted = 1 - 0.5/14 = 0.964286; F = (109/2)/0.5 = 109;
// F(0.95; 2, 6) = 5.14, t(0.975; 6) = 2.447.
DeformationSamples handExample() {
    const double corners[8][3] = {{0.5, 0.1, 100}, {1.5, 0.1, 100}, {0.5, 0.3, 100}, {1.5, 0.3, 100},
                                  {0.5, 0.1, 300}, {1.5, 0.1, 300}, {0.5, 0.3, 300}, {1.5, 0.3, 300}};
    const double y[9] = {10, 16, 13, 20, 11, 16, 13, 21, 15};
    DeformationSamples s;
    s.depthMm.resize(9);
    s.feedMmPerRev.resize(9);
    s.zMm.resize(9);
    s.deformationUm.resize(9);
    for (int i = 0; i < 9; ++i) {
        s.depthMm(i) = i < 8 ? corners[i][0] : 1.0;
        s.feedMmPerRev(i) = i < 8 ? corners[i][1] : 0.2;
        s.zMm(i) = i < 8 ? corners[i][2] : 200.0;
        s.deformationUm(i) = y[i];
    }
    return s;
}

TEST(DeformationFit, HandCheckedFactorialStatistics) {
    const DeformationFit fit = fitDeformationModel(handExample(), DeformationTermSet::Linear, false);
    const LinearRegression& r = fit.regression;
    ASSERT_EQ(r.termCount, 4);
    const double b[4] = {15.0, 3.25, 1.75, 0.25};
    const double se[4] = {0.2357022604, 0.25, 0.25, 0.25};
    const double t[4] = {63.63961031, 13.0, 7.0, 1.0};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(r.coefficients(k), b[k], 1e-12) << k;
        EXPECT_NEAR(r.coefficientStdErrors(k), se[k], 1e-9) << k;
        EXPECT_NEAR(r.tValues(k), t[k], 1e-7) << k;
    }
    EXPECT_NEAR(r.residualSumOfSquares, 2.5, 1e-12);
    EXPECT_NEAR(r.totalSumOfSquares, 112.0, 1e-12);
    EXPECT_NEAR(r.residualSigma, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(fit.twoSigmaUm(), 2.0 * std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(r.r2, 1.0 - 2.5 / 112.0, 1e-12);
    EXPECT_NEAR(r.r2Adjusted, 1.0 - 0.5 / 14.0, 1e-12);
    EXPECT_NEAR(r.fStatistic, 73.0, 1e-9);
    EXPECT_NEAR(r.fCritical95, 5.41, 5e-3);   // table value
    EXPECT_NEAR(r.tCritical95, 2.571, 5e-4);  // table value
    // The coded factors: a in 0.5 .. 1.5 -> centre 1, half range 0.5; the model reproduces the points.
    EXPECT_DOUBLE_EQ(fit.model.coding(DeformationFactor::Depth).centre, 1.0);
    EXPECT_DOUBLE_EQ(fit.model.coding(DeformationFactor::Depth).halfRange, 0.5);
    EXPECT_NEAR(fit.model.deformationUm(1.5, 0.3, 300.0), 15.0 + 3.25 + 1.75 + 0.25, 1e-12);
}

TEST(DeformationFit, StepwiseRemovesTheInsignificantTermAndRefits) {
    const DeformationFit fit = fitDeformationModel(handExample(), DeformationTermSet::Linear, true);
    ASSERT_EQ(fit.removed.size(), 1U);
    EXPECT_EQ(fit.removed[0].term.name(), "z");
    EXPECT_NEAR(fit.removed[0].tValue, 1.0, 1e-9);
    const LinearRegression& r = fit.regression;
    ASSERT_EQ(fit.model.terms().size(), 3U);
    EXPECT_EQ(fit.model.terms()[1].name(), "a");
    EXPECT_EQ(fit.model.terms()[2].name(), "f");
    EXPECT_NEAR(r.coefficients(1), 3.25, 1e-12);
    EXPECT_NEAR(r.coefficients(2), 1.75, 1e-12);
    EXPECT_NEAR(r.residualSumOfSquares, 3.0, 1e-12);
    EXPECT_NEAR(r.coefficientStdErrors(1), 0.25, 1e-12);
    EXPECT_NEAR(r.tValues(1), 13.0, 1e-9);
    EXPECT_NEAR(r.tValues(2), 7.0, 1e-9);
    EXPECT_NEAR(r.r2, 1.0 - 3.0 / 112.0, 1e-12);
    EXPECT_NEAR(r.r2Adjusted, 1.0 - 0.5 / 14.0, 1e-12);
    EXPECT_NEAR(r.fStatistic, 109.0, 1e-9);
    EXPECT_NEAR(r.fCritical95, 5.14, 5e-3);   // table value F(0.95; 2, 6)
    EXPECT_NEAR(r.tCritical95, 2.447, 5e-4);  // table value t(0.975; 6)
    // Without stepwise the same data keep all four terms.
    EXPECT_TRUE(fitDeformationModel(handExample(), DeformationTermSet::Linear, false).removed.empty());
}

TEST(DeformationFit, NamesWhatTheDataCannotSupport) {
    // The corners alone have two levels of a, which cannot separate a^2 (the quadratic set).
    DeformationSamples corners = handExample();
    corners.depthMm.conservativeResize(8);
    corners.feedMmPerRev.conservativeResize(8);
    corners.zMm.conservativeResize(8);
    corners.deformationUm.conservativeResize(8);
    try {
        fitDeformationModel(corners, DeformationTermSet::Quadratic, false);
        FAIL() << "a quadratic in two levels was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("a^2 needs at least 3 different depths of cut a; the data has 2"),
                  std::string::npos)
            << e.what();
    }
    DeformationSamples s = handExample();
    s.feedMmPerRev.setConstant(0.2);
    EXPECT_THROW(fitDeformationModel(s, DeformationTermSet::Linear, false), std::invalid_argument);
    s = handExample();
    s.depthMm(3) = -1.0;
    try {
        fitDeformationModel(s, DeformationTermSet::Linear, false);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("row 4: the depth of cut -1 mm"), std::string::npos) << e.what();
    }
    s = handExample();
    s.zMm.conservativeResize(5);
    EXPECT_THROW(fitDeformationModel(s, DeformationTermSet::Linear, false), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
