#include "core/model/shaping_filter.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <complex>

#include "core/model/disturbance_model.h"

namespace tt::core {
namespace {

using C = std::complex<double>;

// Paper 000 prints W(z) = (0.001 z^2 - 0.0006 z + 0.0004) / (z^3 - 2.024 z^2 + 1.08 z - 0.0561) and
// the roots 0.9969, 0.9692, 0.0580. The rounded coefficients put a root at 1.0029 (SEEDS.md, "Trap"):
// the filter must be refused, naming that root.
TEST(ShapingFilter, RefusesThePapersRoundedCoefficientsNamingTheRoot) {
    try {
        ShapingFilter::fromCoefficients({0.001, -0.0006, 0.0004}, {1, -2.024, 1.08, -0.0561});
        FAIL() << "the rounded filter is unstable";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("unstable"), std::string::npos) << what;
        EXPECT_NE(what.find("root at 1.0029"), std::string::npos) << what;
    }
    const auto roots = ShapingFilter::polynomialRoots({1, -2.024, 1.08, -0.0561});
    EXPECT_NEAR(roots.front().real(), 1.0029, 5e-5);
}

TEST(ShapingFilter, PapersPrintedRootsGiveAStableFilterCloseToThePrintedCoefficients) {
    const ShapingFilter f = ShapingFilter::fromRoots({0.001, -0.0006, 0.0004}, {C(0.9969), C(0.9692), C(0.0580)});
    ASSERT_EQ(f.denominator().size(), 4u);
    // The printed coefficients are these, rounded (to 3-4 digits).
    EXPECT_NEAR(f.denominator()[1], -2.024, 5e-4);
    EXPECT_NEAR(f.denominator()[2], 1.08, 5e-4);
    EXPECT_NEAR(f.denominator()[3], -0.0561, 1e-4);
    EXPECT_NEAR(std::abs(f.poles().front()), 0.9969, 1e-12);
}

// AR(1) as a filter 1/(z - a): unit-input variance 1/(1 - a^2).
TEST(ShapingFilter, FirstOrderVarianceIsTheAr1Formula) {
    const ShapingFilter f = ShapingFilter::fromRoots({1.0}, {C(0.8)});
    EXPECT_NEAR(f.unitInputVariance(), 1.0 / (1.0 - 0.64), 1e-12);
}

// ARMA(1,1) (z + b)/(z - a): impulse response 1, (a + b), (a + b) a, ... so the variance is
// 1 + (a + b)^2 / (1 - a^2) (sum of squares of the impulse response).
TEST(ShapingFilter, BiproperArmaVarianceIsTheImpulseResponseSum) {
    const double a = 0.9215, b = 0.246;
    const ShapingFilter f = ShapingFilter::fromRoots({1.0, b}, {C(a)});
    EXPECT_NEAR(f.unitInputVariance(), 1.0 + (a + b) * (a + b) / (1.0 - a * a), 1e-10);
}

// The realisation reproduces the transfer function: C (zI - A)^-1 G = N(z)/D(z) for a strictly
// proper filter and z^-1 N(z)/D(z) for a biproper one (same output process, renumbered input).
TEST(ShapingFilter, RealisationReproducesTheTransferFunction) {
    const C z(0.3, 1.1);
    auto evaluate = [](const std::vector<double>& p, C x) {
        C v = 0.0;
        for (double c : p)
            v = v * x + c;
        return v;
    };
    for (const auto& num : {std::vector<double>{0.001, -0.0006, 0.0004}, std::vector<double>{1.0, 0.5, -0.2, 0.1}}) {
        const ShapingFilter f = ShapingFilter::fromRoots(num, {C(0.9969), C(0.5, 0.4), C(0.5, -0.4)});
        const DisturbanceRealisation r = f.realise(1.0);
        const Eigen::MatrixXcd I = Eigen::MatrixXcd::Identity(r.A.rows(), r.A.rows());
        const C tf = (r.C.cast<C>() * (z * I - r.A.cast<C>()).inverse() * r.G.cast<C>())(0, 0);
        C expected = evaluate(f.numerator(), z) / evaluate(f.denominator(), z);
        if (f.numerator().size() == f.denominator().size()) expected /= z;
        EXPECT_NEAR(std::abs(tf - expected), 0.0, 1e-10 * std::abs(expected));
    }
}

TEST(ShapingFilter, RefusesBadFilters) {
    EXPECT_THROW(ShapingFilter::fromRoots({1.0}, {C(1.0)}), std::invalid_argument);            // on the circle
    EXPECT_THROW(ShapingFilter::fromRoots({1.0}, {C(0.5, 0.9)}), std::invalid_argument);       // unpaired complex
    EXPECT_THROW(ShapingFilter::fromRoots({1.0, 2.0, 3.0}, {C(0.5)}), std::invalid_argument);  // improper
    EXPECT_THROW(ShapingFilter::fromRoots({0.0}, {C(0.5)}), std::invalid_argument);            // zero numerator
    EXPECT_THROW(ShapingFilter::fromCoefficients({1.0}, {2.0}), std::invalid_argument);        // no root
    EXPECT_THROW(ShapingFilter::fromCoefficients({1.0}, {1.0, std::nan("")}), std::invalid_argument);
    try {
        ShapingFilter::fromRoots({1.0}, {C(-1.5)});
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("root at -1.5"), std::string::npos) << e.what();
    }
}

TEST(DisturbanceModel, SumsComponentsAndRealisesThemBlockDiagonally) {
    const DisturbanceModel m(
        {DisturbanceComponent::ar1(0.9, 0.001), DisturbanceComponent::white(0.0002),
         DisturbanceComponent::shapingFilterWithVariance(ShapingFilter::fromRoots({1.0, 0.246}, {C(0.9215)}), 0.0013)});
    EXPECT_NEAR(m.stationaryVarianceMm2(), 0.001 + 0.0002 + 0.0013, 1e-15);
    const DisturbanceRealisation r = m.realise();
    EXPECT_EQ(r.A.rows(), 1 + 1 + 2);
    EXPECT_EQ(r.G.cols(), 3);
    EXPECT_NEAR(r.W(0, 0), 0.001 * (1 - 0.81), 1e-15);  // AR(1) driving noise
    EXPECT_TRUE(m.isStationary());
    EXPECT_FALSE(DisturbanceModel({DisturbanceComponent::randomWalk(1e-6)}).isStationary());
    EXPECT_TRUE(std::isinf(DisturbanceModel({DisturbanceComponent::randomWalk(1e-6)}).stationaryVarianceMm2()));
}

// Stacking puts each part's states, noise inputs and output on the diagonal: a 1-state AR(1) and a
// 2-state filter give A = diag(A1, A2), G = diag(G1, G2), W = diag(W1, W2), C = [C1 0; 0 C2].
TEST(DisturbanceModel, StackedRealisationsAreBlockDiagonal) {
    const DisturbanceRealisation a = DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.001)}).realise();
    const DisturbanceRealisation b = DisturbanceModel({DisturbanceComponent::shapingFilterWithVariance(
                                                          ShapingFilter::fromRoots({1.0, 0.246}, {C(0.9215)}), 0.0013)})
                                         .realise();
    const DisturbanceRealisation s = stackRealisations({a, b});
    const Eigen::Index na = a.A.rows(), nb = b.A.rows(), qa = a.G.cols(), qb = b.G.cols();
    ASSERT_EQ(s.A.rows(), na + nb);
    ASSERT_EQ(s.G.cols(), qa + qb);
    ASSERT_EQ(s.C.rows(), 2);
    EXPECT_EQ(s.A.topLeftCorner(na, na), a.A);
    EXPECT_EQ(s.A.bottomRightCorner(nb, nb), b.A);
    EXPECT_TRUE(s.A.topRightCorner(na, nb).isZero(0.0));
    EXPECT_TRUE(s.A.bottomLeftCorner(nb, na).isZero(0.0));
    EXPECT_EQ(s.G.topLeftCorner(na, qa), a.G);
    EXPECT_EQ(s.G.bottomRightCorner(nb, qb), b.G);
    EXPECT_TRUE(s.G.topRightCorner(na, qb).isZero(0.0));
    EXPECT_EQ(s.W.topLeftCorner(qa, qa), a.W);
    EXPECT_EQ(s.W.bottomRightCorner(qb, qb), b.W);
    EXPECT_EQ(s.C.block(0, 0, 1, na), a.C);
    EXPECT_EQ(s.C.block(1, na, 1, nb), b.C);
    EXPECT_TRUE(s.C.block(0, na, 1, nb).isZero(0.0));
    EXPECT_TRUE(s.C.block(1, 0, 1, na).isZero(0.0));
}

TEST(DisturbanceModel, RefusesBadComponents) {
    EXPECT_THROW(DisturbanceComponent::ar1(1.0, 0.001), std::invalid_argument);
    EXPECT_THROW(DisturbanceComponent::ar1(0.5, 0.0), std::invalid_argument);
    EXPECT_THROW(DisturbanceComponent::white(-1.0), std::invalid_argument);
    EXPECT_THROW(DisturbanceComponent::randomWalk(std::nan("")), std::invalid_argument);
    EXPECT_THROW(DisturbanceModel({}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
