#include "core/control/lqg_design.h"

#include <gtest/gtest.h>

#include "core/control/lqg_controller.h"
#include "core/linalg/dare.h"
#include "core/sim/statistics/run_to_run_analysis.h"
#include "core/sim/statistics/run_to_run_monte_carlo.h"
#include "support/lqg_test_support.h"

namespace tt::core {
namespace {

double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).norm() / std::max(b.norm(), 1e-300);
}

// The block-structured synthesis (DECISIONS.md) must equal lqry + kalman on the whole plant.
TEST(LqgDesign, BlockSynthesisEqualsWholePlantLqryAndKalman) {
    for (int z = 1; z <= 4; ++z) {
        const RunToRunSetup s = test::paper2012Setup(z);
        const RunToRunPlant p = buildRunToRunPlant(s.plant);
        const LqgDesign blocks = designLqg(p, s.weights);
        const LqgDesign dense = designLqgDense(p, s.weights);
        EXPECT_EQ(blocks.blocks.size(), 5u) << "diagonal R1, R2: one block per point";
        EXPECT_LT(relativeError(blocks.K, dense.K), 1e-9) << "z " << z;
        EXPECT_LT(relativeError(blocks.L, dense.L), 1e-9) << "z " << z;
        EXPECT_LT(relativeError(blocks.P, dense.P), 1e-9) << "z " << z;
        EXPECT_LT(blocks.maxRelativeResidual, 1e-10);
        EXPECT_LT(dense.maxRelativeResidual, 1e-10);
    }
}

TEST(LqgDesign, CoupledWeightsFormOneBlockAndStillEqualTheWholePlantDesign) {
    RunToRunSetup s = test::paper2012Setup(2);
    s.weights.R1(0, 1) = s.weights.R1(1, 0) = 0.3;    // couples points 1 and 2
    s.weights.R2(3, 4) = s.weights.R2(4, 3) = 0.002;  // couples points 4 and 5
    const RunToRunPlant p = buildRunToRunPlant(s.plant);
    const LqgDesign blocks = designLqg(p, s.weights);
    EXPECT_EQ(blocks.blocks.size(), 3u);
    const LqgDesign dense = designLqgDense(p, s.weights);
    EXPECT_LT(relativeError(blocks.K, dense.K), 1e-9);
    EXPECT_LT(relativeError(blocks.L, dense.L), 1e-9);
}

// Minimum variance (Astrom, Introduction to Stochastic Control Theory, 1970, ch. 6): with a perfect
// gauge and free control, the best output is the z-step prediction error of the disturbance. For an
// AR(1) d(k+1) = a d(k) + e(k) of variance s^2 that is sum_{j<z} a^j e, variance s^2 (1 - a^(2z)).
TEST(LqgDesign, CheapControlReachesTheMinimumVarianceOfAnAr1Disturbance) {
    const double a = 0.9, s2 = 1e-3;
    for (int z = 1; z <= 4; ++z) {
        const RunToRunPlant p = test::ar1Plant(z, a, s2, 1e-12);
        const LqgWeights w{Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Constant(1, 1, 1e-8)};
        const SteadyStateVariances v = analyseSteadyState(p, lqgControllerModel(p, designLqg(p, w)));
        EXPECT_NEAR(v.closedMm2(0), s2 * (1 - std::pow(a, 2 * z)), 1e-4 * s2) << "z " << z;
        EXPECT_NEAR(v.openMm2(0), s2, 1e-12);
    }
}

// A random walk is not stabilisable as part of the whole plant (its mode at 1 cannot be moved by u),
// so lqry on the whole plant must refuse it; the block synthesis computes the feed-forward from the
// Stein equation and works.
TEST(LqgDesign, RandomWalkDisturbanceNeedsTheBlockSynthesis) {
    RunToRunPlantSpec spec;
    spec.delay = 2;
    spec.points.push_back(ControlPointSpec{0.0, 2.0, DisturbanceModel({DisturbanceComponent::randomWalk(1e-6)}), 1e-6});
    const RunToRunPlant p = buildRunToRunPlant(spec);
    const LqgWeights w{Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Constant(1, 1, 0.01)};
    EXPECT_THROW(designLqgDense(p, w), DareError);
    const LqgDesign d = designLqg(p, w);
    EXPECT_LT(d.maxRelativeResidual, 1e-10);
    // In closed loop the deviation stays bounded while the disturbance wanders off: z-step prediction
    // error ~ z q plus the gauge, against an open-loop sample variance of order N q / 6.
    LqgController controller(p, d, CorrectionLimits{}, LqgControllerOptions{});
    MonteCarloOptions o;
    o.parts = 20000;
    const MonteCarloResult r = runMonteCarlo(p, controller, o);
    EXPECT_LT(r.points[0].varClosedMm2, 1e-5);
    EXPECT_GT(r.points[0].varOpenMm2, 1e-4);
}

TEST(LqgDesign, RefusesBadWeights) {
    const RunToRunSetup s = test::paper2012Setup(1);
    const RunToRunPlant p = buildRunToRunPlant(s.plant);
    LqgWeights w = s.weights;
    w.R2(2, 2) = 0.0;
    EXPECT_THROW(designLqg(p, w), std::invalid_argument);
    w = s.weights;
    w.R1(0, 0) = -1.0;
    EXPECT_THROW(designLqg(p, w), std::invalid_argument);
    w = s.weights;
    w.R1 = Eigen::MatrixXd::Identity(4, 4);
    EXPECT_THROW(designLqg(p, w), std::invalid_argument);
    w = s.weights;
    w.R1(0, 1) = 0.5;
    EXPECT_THROW(designLqg(p, w), std::invalid_argument);  // not symmetric
}

}  // namespace
}  // namespace tt::core
