#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/model/scaled_polynomial.h"
#include "core/model/systematic_error_model.h"

namespace tt::core {
namespace {

TEST(ScaledPolynomial, ScaledFormEvaluatesAndExpandsToPowerForm) {
    // p(x) = 1 + 2 t - 3 t^2 with t = (x - 100)/50 expands by hand to
    // 1 + 2(x-100)/50 - 3 (x-100)^2/2500 = -15 + 0.28 x - 0.0012 x^2.
    Eigen::VectorXd c(3);
    c << 1.0, 2.0, -3.0;
    const ScaledPolynomial p(c, 100.0, 50.0);
    EXPECT_EQ(p.degree(), 2);
    EXPECT_DOUBLE_EQ(p(100.0), 1.0);
    EXPECT_DOUBLE_EQ(p(150.0), 0.0);
    const Eigen::VectorXd b = p.powerCoefficients();
    EXPECT_NEAR(b(0), -15.0, 1e-13);
    EXPECT_NEAR(b(1), 0.28, 1e-15);
    EXPECT_NEAR(b(2), -0.0012, 1e-18);
    const ScaledPolynomial q = ScaledPolynomial::fromPowerCoefficients(b);
    for (double x : {0.0, 37.0, 100.0, 230.0})
        EXPECT_NEAR(q(x), p(x), 1e-12);
    EXPECT_NEAR(p.derivative(80.0), 0.28 - 2 * 0.0012 * 80.0, 1e-15);
    EXPECT_NEAR(p.scaledBy(-0.5)(80.0), -0.5 * p(80.0), 1e-15);
}

TEST(ScaledPolynomial, LargestMagnitudeIncludesEndsAndStationaryPoints) {
    // p(x) = x^3 - 3x on [-1.5, 3]: stationary points +-1 (|p| = 2), ends p(-1.5) = 1.125, p(3) = 18.
    Eigen::VectorXd b(4);
    b << 0.0, -3.0, 0.0, 1.0;
    const ScaledPolynomial p = ScaledPolynomial::fromPowerCoefficients(b);
    PolynomialPeak peak = p.largestMagnitude(-1.5, 3.0);
    EXPECT_DOUBLE_EQ(peak.x, 3.0);
    EXPECT_DOUBLE_EQ(peak.value, 18.0);
    peak = p.largestMagnitude(-1.5, 1.5);
    EXPECT_NEAR(std::abs(peak.x), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(peak.value), 2.0, 1e-14);
    peak = p.largestMagnitude(-1.2, 0.5);  // only the stationary point -1 inside: p(-1) = 2
    EXPECT_NEAR(peak.x, -1.0, 1e-14);
    EXPECT_NEAR(peak.value, 2.0, 1e-14);
    EXPECT_THROW(p.largestMagnitude(2.0, 1.0), std::invalid_argument);
}

TEST(ScaledPolynomial, ConstantAndZeroPolynomials) {
    const ScaledPolynomial zero;
    EXPECT_EQ(zero(123.0), 0.0);
    EXPECT_EQ(zero.largestMagnitude(0.0, 10.0).value, 0.0);
    Eigen::VectorXd b(1);
    b << -0.02;
    EXPECT_DOUBLE_EQ(ScaledPolynomial::fromPowerCoefficients(b).largestMagnitude(0.0, 325.0).value, -0.02);
}

TEST(ScaledPolynomial, RefusesNonFiniteCoefficientsAndBadScale) {
    Eigen::VectorXd c(2);
    c << 1.0, std::nan("");
    EXPECT_THROW(ScaledPolynomial::fromPowerCoefficients(c), std::invalid_argument);
    EXPECT_THROW(ScaledPolynomial(Eigen::VectorXd::Ones(2), 0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(ScaledPolynomial(Eigen::VectorXd(), 0.0, 1.0), std::invalid_argument);
}

TEST(SystematicErrorModel, FeedForwardIsMinusHalfTheDiameterError) {
    Eigen::VectorXd b(3);
    b << 0.01, 1e-3, -4e-6;
    const SystematicErrorModel m(ScaledPolynomial::fromPowerCoefficients(b), 250.0);
    for (double x : {0.0, 100.0, 250.0}) {
        EXPECT_DOUBLE_EQ(m.feedForwardMm(x), -0.5 * m.diameterErrorMm(x));
        EXPECT_NEAR(m.feedForward()(x), -0.5 * m.diameterErrorMm(x), 1e-17);
    }
    // d = 0.01 + 1e-3 x - 4e-6 x^2 on 0..250 mm peaks at x = 125 mm with d = 0.0725 mm (by hand;
    // the ends give d(0) = 0.01 and d(250) = 0.01).
    EXPECT_NEAR(m.peak().x, 125.0, 1e-9);
    EXPECT_NEAR(m.peak().value, 0.0725, 1e-15);
    EXPECT_THROW(SystematicErrorModel(ScaledPolynomial(), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
