// The chain linearised about its steady state (issue 16, item 3 and "Done when"): the Jacobian against
// finite differences, the eigenvalues against the blocks' own poles, the ODE solution against the
// analytic (modal) solution of the linearised chain, and the stability boundary of the amplifier gain
// against its closed form, cross-checked by simulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "core/sim/hydraulic/feed_linearisation.h"
#include "core/sim/hydraulic/feed_simulation.h"
#include "core/sim/hydraulic/feed_study.h"

namespace tt::core {
namespace {

constexpr double kPaperLoadN = 3.23;

/// The preset hydraulic-feed-chip: the radial force read by the sensor follows the chip thickness (y = 0.6).
HydraulicFeedParams chipParams() {
    HydraulicFeedParams p;
    p.feedExponent = 0.6;
    return p;
}

std::vector<double> asVector(const FeedState& s) {
    return {s.currentA, s.spoolM, s.spoolVelocityMPerS, s.feedMPerS};
}

TEST(FeedLinearisation, JacobianMatchesCentralDifferences) {
    for (const HydraulicFeedParams& p : {HydraulicFeedParams{}, chipParams()}) {
        const HydraulicFeedModel model(p, true);
        const FeedLinearisation lin = linearise(model, kPaperLoadN);
        const FeedState x0 = lin.equilibrium.state;
        const std::vector<double> base = asVector(x0);
        const std::vector<double> steps = {1e-7, 1e-10, 1e-8, 1e-9};
        for (int j = 0; j < 4; ++j) {
            std::vector<double> plus = base, minus = base;
            plus[j] += steps[j];
            minus[j] -= steps[j];
            const std::vector<double> fp =
                asVector(model.derivative({plus[0], plus[1], plus[2], plus[3]}, kPaperLoadN));
            const std::vector<double> fm =
                asVector(model.derivative({minus[0], minus[1], minus[2], minus[3]}, kPaperLoadN));
            for (int i = 0; i < 4; ++i) {
                const double numeric = (fp[i] - fm[i]) / (2.0 * steps[j]);
                EXPECT_NEAR(lin.A(i, j), numeric, 1e-5 * std::max(1.0, std::abs(numeric))) << i << "," << j;
            }
        }
        const double dR = 1e-4;
        const std::vector<double> fp = asVector(model.derivative(x0, kPaperLoadN + dR));
        const std::vector<double> fm = asVector(model.derivative(x0, kPaperLoadN - dR));
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(lin.B(i), (fp[i] - fm[i]) / (2.0 * dR), 1e-6 * std::max(1.0, std::abs(lin.B(i)))) << i;
    }
}

// With the paper's constant force (y = 0) the chain is a cascade: its poles are the blocks' own,
// -r/L (eq. 1), the spool's roots of eq. 10, and -1/T_c (eq. 21), whatever the gain.
TEST(FeedLinearisation, WithoutTheLoopTheEigenvaluesAreTheBlocksPoles) {
    const HydraulicFeedParams p;
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const double root = std::sqrt(p.spoolDampingRatio * p.spoolDampingRatio - 1.0);
    std::vector<double> expected = {-1.0 / d.magnetTimeConstantS, (-p.spoolDampingRatio + root) / p.spoolTimeConstantS,
                                    (-p.spoolDampingRatio - root) / p.spoolTimeConstantS,
                                    -1.0 / d.cylinderTimeConstantS};
    std::sort(expected.begin(), expected.end());
    for (double gain : {10.0, 137.6, 250.0}) {
        HydraulicFeedParams q = p;
        q.amplifierGain = gain;
        const FeedLinearisation lin = linearise(HydraulicFeedModel(q, true), kPaperLoadN);
        std::vector<double> got;
        for (Eigen::Index k = 0; k < 4; ++k) {
            EXPECT_NEAR(lin.eigenvalues(k).imag(), 0.0, 1e-9);
            got.push_back(lin.eigenvalues(k).real());
        }
        std::sort(got.begin(), got.end());
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR(got[k], expected[k], 1e-9 * std::abs(expected[k])) << gain;
        EXPECT_EQ(lin.loopGain, 0.0);
        EXPECT_TRUE(lin.stable());
    }
}

/// Runs the full ODE: the load steps to `load0` at 0, the chain settles, then steps by dR at t1; returns the
/// samples after t1.
std::vector<FeedSample> stepFromSteadyState(const HydraulicFeedParams& p, double load0, double dR, double t1,
                                            double after) {
    FeedLoadProfile load;
    load.addStep(0.0, load0);
    load.addStep(t1, load0 + dR);
    FeedRunOptions options;
    options.durationS = t1 + after;
    options.sampleS = 5e-4;
    const FeedRun run = simulateFeed(HydraulicFeedModel(p, true), load, options);
    std::vector<FeedSample> out;
    for (const FeedSample& s : run.samples)
        if (s.timeS >= t1 - 1e-12) out.push_back(s);
    return out;
}

// "Done when": the ODE solution against the analytic solution of the linearised chain. A load step of 1 %
// from the paper's load; the square law of the magnet and the chip-thickness law are the only
// nonlinearities, so the two agree within 2 % of the largest deviation (their second-order terms are
// about dR / R = 1 % of it).
TEST(FeedLinearisation, OdeSolutionFollowsTheAnalyticLinearisedSolution) {
    for (const HydraulicFeedParams& p : {HydraulicFeedParams{}, chipParams()}) {
        const bool loop = p.feedExponent > 0.0;
        const double t1 = loop ? 8.0 : 0.5;  // the chain has settled on the load (slowest pole 4.8/s or 55/s)
        // Near the fold (loop gain 0.86) the response, and its second-order terms, are amplified by
        // 1 / (1 - 0.86) = 7: the step is 0.1 % there.
        const double dR = (loop ? 0.001 : 0.01) * kPaperLoadN;
        const std::vector<FeedSample> samples = stepFromSteadyState(p, kPaperLoadN, dR, t1, loop ? 1.5 : 0.2);
        const FeedLinearisation lin = linearise(HydraulicFeedModel(p, true), kPaperLoadN);
        std::vector<double> times;
        for (const FeedSample& s : samples)
            times.push_back(s.timeS - t1);
        const std::vector<FeedState> linear = linearStepResponse(lin, dR, times);
        double largest = 0.0, spoolLargest = 0.0;
        for (const FeedState& d : linear) {
            largest = std::max(largest, std::abs(d.feedMPerS));
            spoolLargest = std::max(spoolLargest, std::abs(d.spoolM));
        }
        ASSERT_GT(largest, 1e-6);  // a 1 % load step moves the feed by micrometres per second
        for (std::size_t k = 0; k < samples.size(); ++k) {
            EXPECT_NEAR(samples[k].feedMPerS - lin.equilibrium.state.feedMPerS, linear[k].feedMPerS, 0.02 * largest)
                << "y = " << p.feedExponent << ", t = " << times[k];
            EXPECT_NEAR(samples[k].spoolM - lin.equilibrium.state.spoolM, linear[k].spoolM, 0.02 * spoolLargest)
                << "y = " << p.feedExponent << ", t = " << times[k];
        }
        // Both end at the new steady state: -A^-1 B dR.
        const Eigen::VectorXd finalDx = -lin.A.partialPivLu().solve(lin.B * dR);
        EXPECT_NEAR(linear.back().feedMPerS, finalDx(3), 1e-3 * std::abs(finalDx(3)) + 1e-12);
    }
}

TEST(FeedLinearisation, ModalSolutionNeedsDistinctPoles) {
    HydraulicFeedParams p;
    p.spoolDampingRatio = 1.0;  // repeated spool root: A is defective
    const FeedLinearisation lin = linearise(HydraulicFeedModel(p, true), kPaperLoadN);
    EXPECT_THROW(linearStepResponse(lin, 0.1, {0.0, 0.01}), std::runtime_error);
}

// The loop through the cutting force is positive (more feed, thicker chip, more force, more flow). With
// the paper's magnet F = K_e i^2 (no bias, no lap) the steady feed u = v/S obeys
// u = 1 - b + b (K/K*)^2 u^{2y} (b = k_0 alpha_0 / S = 0.7178, the leakage's share of the feed), which
// folds where 2 y b (K/K*)^2 u^{2y-1} = 1: u = (1 - b) / (1 - 1/(2y)) = 1.6931 and K/K* = 1.02219 for
// y = 0.6. The loop gain at K* is 2 y b = 0.8614.
TEST(FeedStability, GainLimitOfTheChipLoopMatchesItsClosedForm) {
    const HydraulicFeedParams p = chipParams();
    const FeedStability s = analyseStability(p, kPaperLoadN);
    ASSERT_TRUE(s.gainLimit.has_value());
    EXPECT_FALSE(s.fullOpeningGain.has_value());
    const double b = deriveFeedQuantities(p).cylinderGainPerM2 * deriveFeedQuantities(p).leakagePerNewtonM3PerS *
                     kPaperLoadN / p.setFeedMPerS;
    EXPECT_NEAR(b, 0.71782, 1e-5);
    const double y = 0.6;
    const double uFold = (1.0 - b) / (1.0 - 1.0 / (2.0 * y));
    const double ratio = std::sqrt(1.0 / (2.0 * y * b * std::pow(uFold, 2.0 * y - 1.0)));
    EXPECT_NEAR(ratio, 1.02219, 1e-5);
    EXPECT_NEAR(*s.gainLimit / s.designGain, ratio, 1e-5);
    EXPECT_NEAR(s.atGain.loopGain, 2.0 * y * b, 2e-3);  // the preset's gain is K* rounded to 137.6
    EXPECT_TRUE(s.atGain.stable());
    // Just beyond the limit no steady state with the slot partly open is left.
    HydraulicFeedParams beyond = p;
    beyond.amplifierGain = *s.gainLimit * 1.001;
    EXPECT_TRUE(linearise(HydraulicFeedModel(beyond, true), kPaperLoadN).equilibrium.slotFullyOpen);
}

// Cross-check by simulation: at 0.95 of the limit the feed settles where the linearised analysis says; at
// 1.05 it runs away until the slot is fully open.
TEST(FeedStability, SimulationConfirmsTheGainLimit) {
    FeedScenario scenario;
    scenario.params = chipParams();
    scenario.load = FeedLoadProfile::step(0.02, kPaperLoadN);
    const FeedStability s = analyseStability(scenario.params, kPaperLoadN);
    ASSERT_TRUE(s.gainLimit.has_value());
    const FeedBoundaryCheck c = crossCheckGainLimit(scenario, *s.gainLimit);
    EXPECT_TRUE(c.belowSettles) << c.below.feed.finalValue << " vs " << c.predictedFeedMPerS;
    EXPECT_TRUE(c.aboveRunsAway) << c.above.feed.finalValue;
    EXPECT_NEAR(c.below.feed.finalValue, c.predictedFeedMPerS, 1e-3 * c.predictedFeedMPerS);
    // Fully open slot: v = k_0 (Q_y + k_s m_max - alpha_0).
    const HydraulicFeedDerived d = deriveFeedQuantities(scenario.params);
    EXPECT_NEAR(c.above.feed.finalValue,
                d.cylinderGainPerM2 * (d.pumpFlowM3PerS + d.slotGainM2PerS * scenario.params.maxOpeningM -
                                       d.leakagePerNewtonM3PerS * kPaperLoadN),
                1e-6 * 1e-3);
}

// Without the loop (the paper's constant force) no gain destabilises the chain; the gain is limited by the
// slot's full opening instead, at K* sqrt(k_s m_max / alpha_0) = 1.929 K* for the square-law magnet.
TEST(FeedStability, PaperChainHasNoStabilityLimitOnlyTheFullOpening) {
    const HydraulicFeedParams p;
    const FeedStability s = analyseStability(p, kPaperLoadN);
    EXPECT_FALSE(s.gainLimit.has_value());
    ASSERT_TRUE(s.fullOpeningGain.has_value());
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const double expected =
        s.designGain * std::sqrt(d.slotGainM2PerS * p.maxOpeningM / (d.leakagePerNewtonM3PerS * kPaperLoadN));
    EXPECT_NEAR(*s.fullOpeningGain, expected, 1e-6 * expected);
    EXPECT_NEAR(*s.fullOpeningGain / s.designGain, 1.929, 0.001);
}

}  // namespace
}  // namespace tt::core
