// firstCrossing: the bracketed root finding the feed scheduler solves z_i and the feeds with.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/level_crossing.h"

namespace tt::core {
namespace {

ScaledPolynomial power(std::initializer_list<double> b) {
    return ScaledPolynomial::fromPowerCoefficients(
        Eigen::VectorXd::Map(b.begin(), static_cast<Eigen::Index>(b.size())));
}

TEST(FirstCrossing, FindsTheRootOfAMonotonePieceToFullPrecision) {
    // p(x) = x^2 on [0, 3]: p = 2 at sqrt(2) (exact value known).
    const ScaledPolynomial p = power({0.0, 0.0, 1.0});
    const auto up = firstCrossing(p, 2.0, 0.0, 3.0, CrossingSide::AtOrAbove);
    ASSERT_TRUE(up);
    EXPECT_NEAR(*up, std::sqrt(2.0), 4e-15);
    EXPECT_GE(p.value(*up), 2.0);  // the returned point is on the wanted side
    // Travelling down from 3 to 0, the first point at or below 2 is the same root.
    const auto down = firstCrossing(p, 2.0, 3.0, 0.0, CrossingSide::AtOrBelow);
    ASSERT_TRUE(down);
    EXPECT_NEAR(*down, std::sqrt(2.0), 4e-15);
    EXPECT_LE(p.value(*down), 2.0);
}

TEST(FirstCrossing, TakesTheFirstOfSeveralRootsOnTheWay) {
    // p(x) = (x - 1)(x - 2)(x - 3) = x^3 - 6x^2 + 11x - 6: level 0 is crossed at 1, 2 and 3.
    const ScaledPolynomial p = power({-6.0, 11.0, -6.0, 1.0});
    EXPECT_NEAR(*firstCrossing(p, 0.0, 0.0, 4.0, CrossingSide::AtOrAbove), 1.0, 1e-14);
    EXPECT_NEAR(*firstCrossing(p, 0.0, 4.0, 0.0, CrossingSide::AtOrBelow), 3.0, 1e-14);
    // From 1.5 (p > 0) going up, the first point at or below 0 is 2, not 3.
    EXPECT_NEAR(*firstCrossing(p, 0.0, 1.5, 4.0, CrossingSide::AtOrBelow), 2.0, 1e-14);
    // A dip that a coarse scan with 1 mm steps would step over: p(x) = 100 (x - 5.2)(x - 5.4) is
    // negative only on (5.2, 5.4); the bracket between the stationary points finds it.
    const ScaledPolynomial dip = power({100.0 * 5.2 * 5.4, -100.0 * 10.6, 100.0});
    EXPECT_NEAR(*firstCrossing(dip, 0.0, 0.0, 10.0, CrossingSide::AtOrBelow), 5.2, 1e-12);
}

TEST(FirstCrossing, StartsOnTheWantedSideOrNeverGetsThere) {
    const ScaledPolynomial p = power({1.0, 1.0});                                      // p(x) = 1 + x
    EXPECT_DOUBLE_EQ(*firstCrossing(p, 2.0, 5.0, 0.0, CrossingSide::AtOrAbove), 5.0);  // already above at the start
    EXPECT_FALSE(firstCrossing(p, 20.0, 0.0, 5.0, CrossingSide::AtOrAbove));           // never reaches 20
    EXPECT_DOUBLE_EQ(*firstCrossing(p, 6.0, 0.0, 5.0, CrossingSide::AtOrAbove), 5.0);  // touches at the end
    EXPECT_THROW(firstCrossing(p, std::nan(""), 0.0, 5.0, CrossingSide::AtOrAbove), std::invalid_argument);
    EXPECT_THROW(firstCrossing(p, 1.0, 0.0, INFINITY, CrossingSide::AtOrAbove), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
