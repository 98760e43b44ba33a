#include "core/sim/statistics/stochastic_plant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/sim/statistics/normal_stream.h"
#include "support/lqg_test_support.h"

namespace tt::core {
namespace {

// The engine is the standard's: the 10000th output of a default-constructed std::mt19937_64 is
// 9981545732273789042 (C++ standard, [rand.predef]); a seed reproduces a run on every platform.
TEST(NormalStream, EngineIsTheStandardMersenneTwister) {
    std::mt19937_64 engine;
    engine.discard(9999);
    EXPECT_EQ(engine(), 9981545732273789042ULL);
}

TEST(NormalStream, StandardNormalMoments) {
    NormalStream s(3);
    const int n = 200000;
    double sum = 0, sum2 = 0, sum4 = 0;
    for (int i = 0; i < n; ++i) {
        const double x = s.next();
        sum += x;
        sum2 += x * x;
        sum4 += x * x * x * x;
    }
    // Standard errors: mean 1/sqrt(n) = 0.0022, variance sqrt(2/n) = 0.0032, 4th moment sqrt(96/n) = 0.022.
    EXPECT_NEAR(sum / n, 0.0, 0.01);
    EXPECT_NEAR(sum2 / n, 1.0, 0.015);
    EXPECT_NEAR(sum4 / n, 3.0, 0.1);
}

TEST(NormalStream, SaveAndRestoreResumeTheSameSequence) {
    NormalStream a(99);
    a.next();  // a state in the middle of the stream
    const std::string state = a.saveState();
    NormalStream b(1);
    b.restoreState(state);
    for (int i = 0; i < 100; ++i)
        EXPECT_EQ(a.next(), b.next());
    EXPECT_THROW(b.restoreState("garbage"), std::invalid_argument);
}

TEST(StochasticPlant, Ar1VarianceAndCorrelationMatchTheModel) {
    const RunToRunPlant p = test::ar1Plant(1, 0.9, 1e-3, 1e-8);
    StochasticPlant sim(p, 5);
    const int n = 200000;
    double previous = 0, sum2 = 0, lag = 0;
    for (int k = 1; k <= n; ++k) {
        const double d = sim.draw(k).disturbanceMm(0);
        sum2 += d * d;
        if (k > 1) lag += d * previous;
        previous = d;
    }
    // Relative standard error of the AR(1) variance estimate: sqrt(2 (1 + a^2) / ((1 - a^2) n)) = 1 %.
    EXPECT_NEAR(sum2 / n, 1e-3, 4e-5);
    EXPECT_NEAR(lag / sum2, 0.9, 0.005);
}

TEST(StochasticPlant, MachineAddsTheCorrectionTimesTheGainAndTheGaugeNoise) {
    const RunToRunPlant p = test::ar1Plant(2, 0.5, 1e-3, 4e-6, 2);
    StochasticPlant a(p, 8), b(p, 8);
    double noise2 = 0;
    const int n = 50000;
    for (int k = 1; k <= n; ++k) {
        const Eigen::Vector2d u(0.01, -0.02);
        const MachinedPart part = a.machine(k, u);
        const PartDraw& draw = b.draw(k);
        EXPECT_EQ(part.trueDeviationMm, draw.disturbanceMm + 2.0 * u);
        noise2 += std::pow(part.measuredDeviationMm(1) - part.trueDeviationMm(1), 2);
    }
    EXPECT_NEAR(noise2 / n, 4e-6, 4e-6 * 0.03);
    EXPECT_THROW(a.draw(n + 2), std::invalid_argument);
}

TEST(StochasticPlant, SeedsAreReproducibleAndStatesResume) {
    const RunToRunPlant p = buildRunToRunPlant(test::paper2012Setup(3).plant);
    StochasticPlant a(p, 17), b(p, 17), c(p, 18);
    for (int k = 1; k <= 30; ++k) {
        const Eigen::VectorXd da = a.draw(k).disturbanceMm;
        EXPECT_EQ(da, b.draw(k).disturbanceMm);
        EXPECT_NE(da, c.draw(k).disturbanceMm);
    }
    StochasticPlant resumed(p, 1);
    resumed.restoreState(a.saveState());
    for (int k = 31; k <= 60; ++k)
        EXPECT_EQ(a.draw(k).disturbanceMm, resumed.draw(k).disturbanceMm);
    const RunToRunPlant other = test::ar1Plant(3, 0.5, 1e-3, 1e-6);
    StochasticPlant wrong(other, 1);
    EXPECT_THROW(wrong.restoreState(a.saveState()), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
