#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/control/profile_interpolation.h"

namespace tt::core {
namespace {

// Reference data used below (hand computation, exact rationals):
// x = {0, 1, 3, 4}, y = {0, 1, 3, 3.5}: h = {1, 2, 1}, secants del = {1, 1, 0.5}.
//
// PCHIP (Fritsch-Carlson slopes as MATLAB pchip, Moler "Numerical Computing with MATLAB" 3.6):
//   d1 = (w1 + w2) / (w1/del0 + w2/del1), w1 = 2 h1 + h0 = 5, w2 = h1 + 2 h0 = 4   -> 9 / 9 = 1
//   d2: w1 = 2 h2 + h1 = 4, w2 = h2 + 2 h1 = 5  -> 9 / (4/1 + 5/0.5) = 9/14
//   d0 = ((2 h0 + h1) del0 - h0 del1) / (h0 + h1) = (4 - 1) / 3 = 1
//   d3 = ((2 h2 + h1) del2 - h2 del1) / (h2 + h1) = (2 - 1) / 3 = 1/3
//   Hermite cubic: y(0.5) = 1/2, y(2) = 117/56, y(3.5) = 1105/336.
// Natural spline slopes from the tridiagonal system
//   [2 1 0 0; 2 6 1 0; 0 1 6 2; 0 0 1 2] d = [3; 9; 7.5; 1.5]  ->  d = {31/32, 17/16, 11/16, 13/32},
//   y(0.5) = 125/256, y(2) = 67/32, y(3.5) = 841/256.
const std::vector<double> kX = {0.0, 1.0, 3.0, 4.0};
const std::vector<double> kY = {0.0, 1.0, 3.0, 3.5};

TEST(Pchip, SlopesMatchHandComputedFritschCarlson) {
    const PiecewiseCubic p = PiecewiseCubic::pchip(kX, kY);
    const std::vector<double> expected = {1.0, 1.0, 9.0 / 14.0, 1.0 / 3.0};
    ASSERT_EQ(p.knotSlopes().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(p.knotSlopes()[i], expected[i], 1e-15) << "slope " << i;
}

TEST(Pchip, ValuesMatchHandComputedReference) {
    const PiecewiseCubic p = PiecewiseCubic::pchip(kX, kY);
    EXPECT_NEAR(p(0.5), 0.5, 1e-15);
    EXPECT_NEAR(p(2.0), 117.0 / 56.0, 1e-15);
    EXPECT_NEAR(p(3.5), 1105.0 / 336.0, 1e-15);
    for (std::size_t i = 0; i < kX.size(); ++i)
        EXPECT_DOUBLE_EQ(p(kX[i]), kY[i]) << "passes through knot " << i;
}

TEST(Pchip, LocalExtremumGetsZeroSlopeAndShapePreservingEnds) {
    // y = {0, 1, 1, 0} on 0..3: del = {1, 0, -1}; interior slopes 0 (flat piece),
    // end slopes 3/2 and -3/2 (pchipend), so y(0.5) = 0.5 (3/2 + 0.5 (0 - 0.25)) = 0.6875 (by hand).
    const PiecewiseCubic p = PiecewiseCubic::pchip({0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 1.0, 0.0});
    EXPECT_DOUBLE_EQ(p.knotSlopes()[0], 1.5);
    EXPECT_DOUBLE_EQ(p.knotSlopes()[1], 0.0);
    EXPECT_DOUBLE_EQ(p.knotSlopes()[2], 0.0);
    EXPECT_DOUBLE_EQ(p.knotSlopes()[3], -1.5);
    EXPECT_NEAR(p(0.5), 0.6875, 1e-15);
    EXPECT_DOUBLE_EQ(p(1.5), 1.0);  // flat data stay flat: no bump between equal values
}

TEST(Pchip, EndSlopeIsLimitedToThreeSecantsWhenTheDataTurn) {
    // x = {0, 1, 2}, y = {0, 1, -10}: three-point end slope ((2+1)*1 - 1*(-11))/2 = 7 > 3 del0 = 3,
    // and the secants change sign, so MATLAB's pchipend caps it at 3 (hand computation).
    const PiecewiseCubic p = PiecewiseCubic::pchip({0.0, 1.0, 2.0}, {0.0, 1.0, -10.0});
    EXPECT_DOUBLE_EQ(p.knotSlopes()[0], 3.0);
}

TEST(Pchip, MonotoneDataGiveAMonotoneCurveWhereTheSplineOvershoots) {
    // Fritsch & Carlson (1980), SIAM J. Numer. Anal. 17(2), "RPN 14" radiochemical data: monotone.
    const std::vector<double> x = {7.99, 8.09, 8.19, 8.7, 9.2, 10.0, 12.0, 15.0, 20.0};
    const std::vector<double> y = {0.0,      2.76429e-5, 4.37498e-2, 0.169183, 0.469428,
                                   0.943740, 0.998636,   0.999919,   0.999994};
    const PiecewiseCubic p = PiecewiseCubic::pchip(x, y);
    const PiecewiseCubic s = PiecewiseCubic::naturalSpline(x, y);
    double previous = p(x.front());
    bool splineLeavesRange = false;
    for (int i = 1; i <= 12000; ++i) {
        const double xi = x.front() + (x.back() - x.front()) * i / 12000.0;
        const double v = p(xi);
        EXPECT_GE(v, previous - 1e-15) << "pchip decreases at x = " << xi;
        EXPECT_GE(v, y.front());
        EXPECT_LE(v, y.back() + 1e-15);
        previous = v;
        if (s(xi) > y.back() + 1e-6 || s(xi) < y.front() - 1e-6) splineLeavesRange = true;
    }
    EXPECT_TRUE(splineLeavesRange) << "the natural spline is expected to overshoot on these data";
}

TEST(Pchip, TwoPointsGiveTheStraightLineAndOnePointAConstant) {
    const PiecewiseCubic line = PiecewiseCubic::pchip({10.0, 20.0}, {1.0, 3.0});
    EXPECT_DOUBLE_EQ(line(15.0), 2.0);
    EXPECT_DOUBLE_EQ(line(12.5), 1.5);
    const PiecewiseCubic one = PiecewiseCubic::pchip({100.0}, {0.02});
    for (double x : {-5.0, 0.0, 100.0, 325.0})
        EXPECT_DOUBLE_EQ(one(x), 0.02);
    const PiecewiseCubic oneSpline = PiecewiseCubic::naturalSpline({100.0}, {0.02});
    EXPECT_DOUBLE_EQ(oneSpline(7.0), 0.02);
}

TEST(Pchip, LinearDataAreReproducedExactly) {
    const std::vector<double> x = {0.0, 25.0, 162.5, 270.0, 325.0};
    std::vector<double> y;
    for (double xi : x)
        y.push_back(0.01 - 0.0002 * xi);
    const PiecewiseCubic p = PiecewiseCubic::pchip(x, y);
    const PiecewiseCubic s = PiecewiseCubic::naturalSpline(x, y);
    for (double xi = 0.0; xi <= 325.0; xi += 7.3) {
        EXPECT_NEAR(p(xi), 0.01 - 0.0002 * xi, 1e-15);
        EXPECT_NEAR(s(xi), 0.01 - 0.0002 * xi, 1e-15);
    }
}

TEST(Interpolation, OutsideTheKnotsTheEndValueIsHeld) {
    for (InterpolationMethod m : {InterpolationMethod::Pchip, InterpolationMethod::NaturalSpline}) {
        const PiecewiseCubic p = PiecewiseCubic::make(m, kX, kY);
        EXPECT_DOUBLE_EQ(p(-100.0), kY.front());
        EXPECT_DOUBLE_EQ(p(-1e-9), kY.front());
        EXPECT_DOUBLE_EQ(p(4.0 + 1e-9), kY.back());
        EXPECT_DOUBLE_EQ(p(1e6), kY.back());
        EXPECT_DOUBLE_EQ(p.derivative(-1.0), 0.0);
    }
}

TEST(NaturalSpline, ValuesMatchHandComputedReference) {
    const PiecewiseCubic s = PiecewiseCubic::naturalSpline(kX, kY);
    const std::vector<double> slopes = {31.0 / 32.0, 17.0 / 16.0, 11.0 / 16.0, 13.0 / 32.0};
    for (std::size_t i = 0; i < slopes.size(); ++i)
        EXPECT_NEAR(s.knotSlopes()[i], slopes[i], 1e-15) << "slope " << i;
    EXPECT_NEAR(s(0.5), 125.0 / 256.0, 1e-15);
    EXPECT_NEAR(s(2.0), 67.0 / 32.0, 1e-15);
    EXPECT_NEAR(s(3.5), 841.0 / 256.0, 1e-15);
}

TEST(NaturalSpline, ThreePointTextbookExample) {
    // x = {0, 1, 2}, y = {0, 1, 0}: M1 = -3 from 4 M1 = 6 (del1 - del0), so on [0, 1]
    // S(x) = -x^3/2 + 3x/2 (Burden & Faires, natural cubic spline construction): S(0.5) = 0.6875.
    const PiecewiseCubic s = PiecewiseCubic::naturalSpline({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0});
    EXPECT_NEAR(s(0.5), 0.6875, 1e-15);
    EXPECT_NEAR(s(1.5), 0.6875, 1e-15);
    EXPECT_NEAR(s.derivative(0.0), 1.5, 1e-15);
    EXPECT_NEAR(s.derivative(1.0), 0.0, 1e-15);
}

TEST(NaturalSpline, SecondDerivativeIsContinuousAndZeroAtTheEnds) {
    const std::vector<double> x = {0.0, 27.0, 162.5, 265.0, 325.0};
    const std::vector<double> y = {0.004, -0.012, 0.020, -0.007, 0.011};
    const PiecewiseCubic s = PiecewiseCubic::naturalSpline(x, y);
    const double e = 1e-3;
    auto second = [&](double xi, double side) {  // one-sided second difference of the derivative
        return side * (s.derivative(xi + side * e) - s.derivative(xi)) / e;
    };
    EXPECT_NEAR(second(x.front(), 1.0), 0.0, 1e-7);
    EXPECT_NEAR(second(x.back(), -1.0), 0.0, 1e-7);
    for (std::size_t i = 1; i + 1 < x.size(); ++i)
        EXPECT_NEAR(second(x[i], -1.0), second(x[i], 1.0), 1e-7) << "y'' jumps at knot " << i;
}

TEST(Interpolation, BadInputIsRefusedWithAReason) {
    EXPECT_THROW(PiecewiseCubic::pchip({}, {}), std::invalid_argument);
    EXPECT_THROW(PiecewiseCubic::pchip({0.0, 1.0}, {0.0}), std::invalid_argument);
    EXPECT_THROW(PiecewiseCubic::pchip({0.0, 0.0}, {0.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(PiecewiseCubic::naturalSpline({1.0, 0.0}, {0.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(PiecewiseCubic::pchip({0.0, 1.0}, {0.0, std::nan("")}), std::invalid_argument);
    EXPECT_THROW(PiecewiseCubic::pchip({0.0, INFINITY}, {0.0, 1.0}), std::invalid_argument);
    try {
        PiecewiseCubic::pchip({0.0, 2.0, 1.0}, {0.0, 1.0, 2.0});
        FAIL() << "unsorted positions must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("point 3"), std::string::npos) << e.what();
    }
}

TEST(Interpolation, MethodNamesRoundTrip) {
    EXPECT_EQ(interpolationMethodFromName("pchip"), InterpolationMethod::Pchip);
    EXPECT_EQ(interpolationMethodFromName("spline"), InterpolationMethod::NaturalSpline);
    EXPECT_EQ(interpolationMethodName(InterpolationMethod::NaturalSpline), "spline");
    EXPECT_EQ(interpolationMethodName(InterpolationMethod::Pchip), "pchip");
    EXPECT_THROW(interpolationMethodFromName("akima"), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
