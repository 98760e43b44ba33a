// The feed stabiliser's chain as one ODE (paper 003, shared/seeds/003_*.txt): the right-hand side,
// the steady states, and the paper's two headline feeds on the preset's parameters (issue 16: steady
// feed 2.8e-4 m/s +-10 % without the regulator and 1e-3 m/s +-10 % with it, the transient taking
// about the same time in both cases).
#include <gtest/gtest.h>

#include <cmath>

#include "core/sim/hydraulic/feed_simulation.h"
#include "core/sim/hydraulic/hydraulic_feed_blocks.h"
#include "core/sim/hydraulic/hydraulic_feed_model.h"

namespace tt::core {
namespace {

constexpr double kPaperLoadN = 3.23;  // the load of the paper's alpha_0 (printed as R_tp = 3.23)

TEST(FeedModel, RightHandSideIsTheChainOfBlocks) {
    HydraulicFeedParams p;
    p.feedExponent = 0.6;
    p.spoolLapM = 2e-5;
    p.biasVoltageV = 0.3;
    const HydraulicFeedModel model(p, true);
    const HydraulicFeedDerived& d = model.derived();
    const FeedState x{0.021, 1.3e-4, 2e-3, 0.8e-3};
    const double load = 5.0;
    const FeedState dx = model.derivative(x, load);
    const double u = p.biasVoltageV + p.amplifierGain * p.sensorGainVPerN * load * std::pow(0.8, 0.6);
    EXPECT_DOUBLE_EQ(model.amplifierVoltage(load, x.feedMPerS), u);
    EXPECT_DOUBLE_EQ(dx.currentA, (u - p.coilResistanceOhm * x.currentA) / d.coilInductanceH);
    EXPECT_DOUBLE_EQ(dx.spoolM, x.spoolVelocityMPerS);
    const double force = d.armatureGainNPerA2 * x.currentA * x.currentA;
    EXPECT_DOUBLE_EQ(dx.spoolVelocityMPerS, (p.spoolGainMPerN * force - x.spoolM -
                                             2.0 * p.spoolDampingRatio * p.spoolTimeConstantS * x.spoolVelocityMPerS) /
                                                (p.spoolTimeConstantS * p.spoolTimeConstantS));
    const double flow = d.pumpFlowM3PerS + d.slotGainM2PerS * (x.spoolM - p.spoolLapM);
    const double leak = d.leakagePerNewtonM3PerS * load;
    EXPECT_NEAR(dx.feedMPerS, (d.cylinderGainPerM2 * (flow - leak) - x.feedMPerS) / d.cylinderTimeConstantS,
                1e-12 * std::abs(dx.feedMPerS));
    // Regulator off: the magnet is unpowered.
    const HydraulicFeedModel off(p, false);
    EXPECT_DOUBLE_EQ(off.amplifierVoltage(load, x.feedMPerS), 0.0);
    EXPECT_DOUBLE_EQ(off.derivative(x, load).currentA, -p.coilResistanceOhm * x.currentA / d.coilInductanceH);
}

TEST(FeedModel, SteadyStatesAreRestPointsOfTheRightHandSide) {
    for (bool on : {false, true}) {
        const HydraulicFeedModel model(HydraulicFeedParams{}, on);
        const FeedState unloaded = model.unloadedState();
        EXPECT_NEAR(unloaded.feedMPerS, 1e-3, 1e-15);
        for (double load : {0.0, kPaperLoadN, 2.0}) {
            const FeedEquilibrium e = model.equilibrium(load);
            const FeedState dx = model.derivative(e.state, load);
            EXPECT_NEAR(dx.currentA, 0.0, 1e-9);
            EXPECT_NEAR(dx.spoolVelocityMPerS, 0.0, 1e-6);
            EXPECT_NEAR(dx.feedMPerS, 0.0, 1e-10);
        }
    }
    // The design gain makes up exactly the leakage at the set feed, with or without the loop through the
    // cutting force (the sensed force equals the load at the set feed).
    for (double exponent : {0.0, 0.6}) {
        HydraulicFeedParams p;
        p.feedExponent = exponent;
        p.amplifierGain = designAmplifierGain(p, kPaperLoadN);
        EXPECT_NEAR(HydraulicFeedModel(p, true).equilibrium(kPaperLoadN).state.feedMPerS, 1e-3, 1e-12);
    }
}

// Issue 16, item 2 and "Done when": under the paper's load the steady feed is 2.8e-4 m/s +-10 % with the
// regulator off and 1e-3 m/s +-10 % with it on (paper: V = 2.8e-4 and 1e-3 m/s).
TEST(FeedModel, ReproducesThePaperHeadlineFeeds) {
    const FeedLoadProfile load = FeedLoadProfile::step(0.02, kPaperLoadN);
    const FeedRun off = simulateFeed(HydraulicFeedModel(HydraulicFeedParams{}, false), load, {});
    const FeedRun on = simulateFeed(HydraulicFeedModel(HydraulicFeedParams{}, true), load, {});
    EXPECT_NEAR(off.feed.finalValue, 2.8e-4, 0.1 * 2.8e-4);
    EXPECT_NEAR(on.feed.finalValue, 1.0e-3, 0.1 * 1.0e-3);
    EXPECT_TRUE(off.feed.settled);
    EXPECT_TRUE(on.feed.settled);
    // Closer than the paper's rounding: 1e-3 - 56.588 x 1.268e-5 = 2.82e-4; the design gain is rounded to 137.6.
    EXPECT_NEAR(off.feed.finalValue, 2.822e-4, 0.001e-4);
    EXPECT_NEAR(on.feed.finalValue, 1.0e-3, 0.001e-3);
    EXPECT_GT(on.samples.back().regulatorFlowM3PerS, 1.26e-5);  // the regulator gives the leakage back
    EXPECT_EQ(off.samples.back().regulatorFlowM3PerS, 0.0);
}

// The paper: "the duration of the transient is about the same in both cases". Here: with the regulator
// the feed settles (5 % band) within 1.5 times the unregulated 3 T_c = 0.054 s (measured 1.14 from rest,
// 1.32 for a load step at the set feed).
TEST(FeedModel, TransientTakesAboutTheSameTimeWithAndWithoutTheRegulator) {
    for (bool fromRest : {true, false}) {
        FeedRunOptions options;
        options.fromRest = fromRest;
        const FeedLoadProfile load = FeedLoadProfile::step(fromRest ? 0.0 : 0.02, kPaperLoadN);
        const FeedRun off = simulateFeed(HydraulicFeedModel(HydraulicFeedParams{}, false), load, options);
        const FeedRun on = simulateFeed(HydraulicFeedModel(HydraulicFeedParams{}, true), load, options);
        // Without the regulator the cylinder is the first-order link of eq. 21: t_c = 3 T_c.
        EXPECT_NEAR(off.feed.settlingS, 3.0 * 0.018, 0.0005) << fromRest;
        const double ratio = on.feed.settlingS / off.feed.settlingS;
        EXPECT_GT(ratio, 0.7) << fromRest;
        EXPECT_LT(ratio, 1.5) << fromRest;
    }
}

// From rest with the regulator off the whole ODE must give eq. 22: V = k_0 (Q_y - alpha_0)(1 - e^{-t/T_c}).
TEST(FeedModel, StartFromRestWithoutRegulatorIsEquationTwentyTwo) {
    const HydraulicFeedModel model(HydraulicFeedParams{}, false);
    FeedRunOptions options;
    options.fromRest = true;
    options.durationS = 0.2;
    const FeedRun run = simulateFeed(model, FeedLoadProfile::step(0.0, kPaperLoadN), options);
    const HydraulicFeedDerived& d = model.derived();
    const double final = d.cylinderGainPerM2 * (d.pumpFlowM3PerS - d.leakagePerNewtonM3PerS * kPaperLoadN);
    ASSERT_EQ(run.samples.size(), 401u);
    for (const FeedSample& s : run.samples)
        EXPECT_NEAR(s.feedMPerS, final * (1.0 - std::exp(-s.timeS / d.cylinderTimeConstantS)), 1e-10) << s.timeS;
}

TEST(FeedModel, RampOfTheLoadEndsWhereTheStepDoes) {
    FeedLoadProfile ramp;
    ramp.addRamp(0.02, 0.1, kPaperLoadN);
    const HydraulicFeedModel off(HydraulicFeedParams{}, false);
    const FeedRun run = simulateFeed(off, ramp, {});
    EXPECT_NEAR(run.feed.finalValue, off.equilibrium(kPaperLoadN).state.feedMPerS, 1e-9);
    // Half-way up the ramp the load is half.
    EXPECT_NEAR(run.samples[140].loadN, kPaperLoadN / 2.0, 1e-9);  // t = 0.07 s
    EXPECT_NEAR(run.samples[140].timeS, 0.07, 1e-12);
}

TEST(FeedModel, SimulationChecksItsOptionsAndCanBeCancelled) {
    const HydraulicFeedModel model(HydraulicFeedParams{}, true);
    const FeedLoadProfile load = FeedLoadProfile::step(0.02, kPaperLoadN);
    EXPECT_THROW(simulateFeed(model, load, {0.0, 1e-3}), std::invalid_argument);
    EXPECT_THROW(simulateFeed(model, load, {100.0, 1e-3}), std::invalid_argument);
    EXPECT_THROW(simulateFeed(model, load, {10.0, 1e-6}), std::invalid_argument);  // 1e7 samples
    int asked = 0;
    EXPECT_THROW(simulateFeed(model, load, {}, [&] { return ++asked > 10; }), FeedSimulationCancelled);
    EXPECT_EQ(asked, 11);
}

TEST(FeedLoadProfile, StepsAndRamps) {
    FeedLoadProfile p;
    EXPECT_EQ(p.forceAt(1.0), 0.0);
    p.addStep(0.1, 3.0);
    p.addRamp(0.2, 0.1, 5.0);
    p.addStep(0.05, 1.0);  // added out of order
    EXPECT_EQ(p.forceAt(0.04), 0.0);
    EXPECT_EQ(p.forceAt(0.05), 1.0);
    EXPECT_EQ(p.forceAt(0.1), 3.0);
    EXPECT_NEAR(p.forceAt(0.25), 4.0, 1e-12);
    EXPECT_EQ(p.forceAt(0.4), 5.0);
    EXPECT_EQ(p.breakpoints(), (std::vector<double>{0.05, 0.1, 0.2, 0.2 + 0.1}));
    EXPECT_EQ(p.lastEventS(), 0.2);
    EXPECT_EQ(p.maxForceN(), 5.0);
    EXPECT_THROW(p.addStep(0.25, 1.0), std::invalid_argument);  // inside the ramp
    EXPECT_THROW(p.addStep(0.1, 2.0), std::invalid_argument);   // same time as another change
    EXPECT_THROW(p.addStep(-1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(p.addStep(1.0, 2e4), std::invalid_argument);
    EXPECT_THROW(p.addRamp(1.0, 0.0, 1.0), std::invalid_argument);
    try {
        p.addStep(70.0, 1.0);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "load time 70 s is outside 0 .. 60 s");
    }
}

}  // namespace
}  // namespace tt::core
