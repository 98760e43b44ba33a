// The feedback regulator of the feed (paper 003 beyond its preset): the linearised chain (eqs. 2, 13, 15, 22),
// the design and its margins against scipy.signal (scripts/crosscheck-feed-margins.py, scipy 1.10.1, same
// transfer function), the margins of textbook loops, the steady states with the stop at zero feed, and the
// feed held within +-3 % of the set feed for loads 0.5 .. 6 N, a ramp 1 -> 6 N over 0.2 s and a step
// sequence, settling within 3 T_c (the paper's t_c = 3T of the cylinder).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/control/continuous_margins.h"
#include "core/sim/hydraulic/feed_study.h"

namespace tt::core {
namespace {

constexpr double kBandPct = 3.0;  // the tolerance asked of the regulator: +-3 % of the set feed

// A textbook loop with closed-form margins: L = K / (s (s + 1)(s + 2)) crosses -180 deg at w = sqrt 2, where
// |L| = K / 6, so the gain margin is 6 / K; phase margins and poles: scipy.signal (crosscheck script's margins()).
TEST(ContinuousMargins, TextbookThirdOrderLoop) {
    const ContinuousMargins m = continuousMargins({{1.0}, {1.0, 3.0, 2.0, 0.0}}, 1e-3, 1e3);
    ASSERT_TRUE(m.gainMargin && m.phaseMarginDeg);
    EXPECT_NEAR(*m.gainMargin, 6.0, 1e-9);
    EXPECT_NEAR(*m.gainMarginDb(), 20.0 * std::log10(6.0), 1e-9);
    EXPECT_NEAR(*m.phaseCrossoverRadPerS, std::numbers::sqrt2, 1e-9);
    EXPECT_NEAR(*m.phaseMarginDeg, 53.41078617769915, 1e-7);  // scipy
    EXPECT_NEAR(*m.gainCrossoverRadPerS, 0.4457479596318948, 1e-9);
    EXPECT_NEAR(*m.delayMarginS, 53.41078617769915 * std::numbers::pi / 180.0 / 0.4457479596318948, 1e-7);
    EXPECT_TRUE(m.closedLoopStable);
    ASSERT_EQ(m.closedLoopPoles.size(), 3u);
    // Beyond the gain margin the closed loop is unstable.
    const ContinuousMargins beyond = continuousMargins({{6.5}, {1.0, 3.0, 2.0, 0.0}}, 1e-3, 1e3);
    EXPECT_FALSE(beyond.closedLoopStable);
    // A first-order loop a / s: phase margin 90 deg at w = a, no gain margin.
    const ContinuousMargins integrator = continuousMargins({{50.0}, {1.0, 0.0}}, 1e-2, 1e4);
    EXPECT_FALSE(integrator.gainMargin);
    EXPECT_NEAR(*integrator.phaseMarginDeg, 90.0, 1e-9);
    EXPECT_NEAR(*integrator.gainCrossoverRadPerS, 50.0, 1e-9);
    ASSERT_EQ(integrator.closedLoopPoles.size(), 1u);
    EXPECT_NEAR(integrator.closedLoopPoles[0].real(), -50.0, 1e-9);
    EXPECT_THROW(continuousMargins({{1.0, 0.0, 0.0}, {1.0, 1.0}}, 1.0, 10.0), std::invalid_argument);  // improper
    EXPECT_THROW(continuousMargins({{1.0}, {1.0, 1.0}}, 10.0, 1.0), std::invalid_argument);
}

// G(s) = k_s k_0 / ((T_k s + 1)(T_z^2 s^2 + 2 xi T_z s + 1)(T_c s + 1)) with the preset's derived values
// (tests/core/sim/hydraulic/feed_blocks_test.cpp checks each: k_0 = 1/F, T_c = M k_y / F^2, T_k = L / r, k_s).
TEST(FeedFeedback, PlantIsThePapersChainInSeries) {
    const HydraulicFeedParams p;
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const RationalTransfer g = feedPlantTransfer(p);
    ASSERT_EQ(g.numerator.size(), 1u);
    EXPECT_NEAR(g.numerator[0], d.slotGainM2PerS * d.cylinderGainPerM2, 1e-12);
    EXPECT_NEAR(g.numerator[0], 6.67839, 1e-5);  // 0.11802 m^2/s x 56.588 m^-2
    ASSERT_EQ(g.denominator.size(), 5u);
    const double tk = d.magnetTimeConstantS, tz = p.spoolTimeConstantS, tc = d.cylinderTimeConstantS;
    EXPECT_NEAR(g.denominator[0], tk * tz * tz * tc, 1e-20);
    EXPECT_NEAR(g.denominator[3], tk + 2.0 * p.spoolDampingRatio * tz + tc, 1e-15);
    EXPECT_EQ(g.denominator[4], 1.0);
    EXPECT_NEAR(std::abs(g.at(1e-6)), g.numerator[0], 1e-9);  // the static gain
}

// The design on the preset and its margins: the same loop in scipy.signal gives gain margin 4.714350008609085
// at 550.4787338643778 rad/s, phase margin 50.00011544262796 deg at 182.39180963971924 rad/s and the closed-loop
// poles below (scripts/crosscheck-feed-margins.py; tolerance 1e-7 relative, the bisection's and the grid's).
TEST(FeedFeedback, DesignAndMarginsAgreeWithScipy) {
    const FeedFeedbackDesign d = designFeedFeedback(HydraulicFeedParams{});
    const HydraulicFeedDerived q = deriveFeedQuantities(HydraulicFeedParams{});
    EXPECT_NEAR(d.integralTimeS, q.cylinderTimeConstantS / 1.5, 1e-15);
    EXPECT_NEAR(d.leadTimeS, 0.003 * (1.2 + std::sqrt(1.2 * 1.2 - 1.0)), 1e-15);  // the spool's slower pole
    EXPECT_NEAR(d.filterTimeS, d.leadTimeS / 10.0, 1e-15);
    // Regression pin of the design (its loop is the one scipy checked): K_p = 0.4976 s.
    EXPECT_NEAR(d.gainS, 0.497574, 1e-5);
    const ContinuousMargins& m = d.margins;
    ASSERT_TRUE(m.gainMargin && m.phaseMarginDeg && m.delayMarginS);
    EXPECT_NEAR(*m.gainMargin, 4.714350008609085, 1e-7 * 4.7);
    EXPECT_NEAR(*m.phaseCrossoverRadPerS, 550.4787338643778, 1e-7 * 550.0);
    EXPECT_NEAR(*m.phaseMarginDeg, 50.00011544262796, 1e-6);
    EXPECT_NEAR(*m.gainCrossoverRadPerS, 182.39180963971924, 1e-7 * 182.0);
    EXPECT_NEAR(*m.delayMarginS, 50.00011544262796 * std::numbers::pi / 180.0 / 182.39180963971924, 1e-9);
    EXPECT_TRUE(m.closedLoopStable);
    double slowest = -1e9;
    for (const auto& pole : m.closedLoopPoles)
        slowest = std::max(slowest, pole.real());
    EXPECT_NEAR(slowest, -101.0354597, 1e-4);  // scipy: numpy.roots of den + num
    // The design holds its targets over the spool's damping, the oscillating spool included.
    for (double xi : {0.2, 0.5, 0.8, 1.0, 2.0}) {
        HydraulicFeedParams p;
        p.spoolDampingRatio = xi;
        const FeedFeedbackDesign e = designFeedFeedback(p);
        EXPECT_TRUE(e.margins.closedLoopStable) << xi;
        EXPECT_GE(*e.margins.gainMargin, 2.5 - 1e-6) << xi;
        EXPECT_GE(*e.margins.phaseMarginDeg, 50.0 - 1e-3) << xi;
    }
    EXPECT_THROW(scaledFeedback(d, 0.0), std::invalid_argument);
    EXPECT_FALSE(scaledFeedback(d, 1.05 * *m.gainMargin).margins.closedLoopStable);
    EXPECT_TRUE(scaledFeedback(d, 0.95 * *m.gainMargin).margins.closedLoopStable);
}

double swing(const FeedRun& run, double fromS, double toS) {
    double lo = 1e9, hi = -1e9;
    for (const FeedSample& s : run.samples)
        if (s.timeS >= fromS && s.timeS < toS) {
            lo = std::min(lo, s.feedMPerS);
            hi = std::max(hi, s.feedMPerS);
        }
    return hi - lo;
}

// The margins computed on the linearised chain hold on the full model (square law, characteriser, clamps):
// at 0.9 x the gain margin a small load step dies out, at 1.1 x it keeps oscillating (on the slot's limits).
TEST(FeedFeedback, GainMarginIsTheFullModelsBoundary) {
    const HydraulicFeedParams p;
    const FeedFeedbackDesign d = designFeedFeedback(p);
    FeedLoadProfile load;
    load.addStep(0.02, 3.0);
    load.addStep(0.2, 3.2);
    FeedRunOptions o;
    o.durationS = 0.6;
    o.sampleS = 2e-4;
    const FeedRun below = simulateFeed(
        HydraulicFeedModel(p, FeedRegulator::Feedback, scaledFeedback(d, 0.9 * *d.margins.gainMargin)), load, o);
    const FeedRun above = simulateFeed(
        HydraulicFeedModel(p, FeedRegulator::Feedback, scaledFeedback(d, 1.1 * *d.margins.gainMargin)), load, o);
    EXPECT_LT(swing(below, 0.5, 0.6), 0.05 * swing(below, 0.2, 0.3));
    EXPECT_GT(swing(above, 0.5, 0.6), 0.5 * swing(above, 0.2, 0.3));
    EXPECT_GT(swing(above, 0.5, 0.6), 0.01 * p.setFeedMPerS);
}

// The steady states are rest points of the right-hand side, with the slot partly open, fully open, and the
// carriage stalled on its stop (13 N needs 0.433 mm of the 0.4 mm slot; at 20 N the fully open slot's
// 4.7e-5 m^3/s and the pump's 1.77e-5 cannot make up 7.9e-5 m^3/s).
TEST(FeedFeedback, SteadyStatesAndTheStop) {
    const HydraulicFeedModel model(HydraulicFeedParams{}, FeedRegulator::Feedback);
    for (double load : {0.0, 0.5, 3.23, 6.0, 13.0, 20.0}) {
        const FeedEquilibrium e = model.equilibrium(load);
        const FeedState dx = model.derivative(e.state, load);
        EXPECT_NEAR(dx.currentA, 0.0, 1e-9) << load;
        EXPECT_NEAR(dx.spoolVelocityMPerS, 0.0, 1e-6) << load;
        EXPECT_NEAR(dx.feedMPerS, 0.0, 1e-10) << load;
        EXPECT_NEAR(dx.integralM, 0.0, 1e-12) << load;
        EXPECT_NEAR(dx.leadM, 0.0, 1e-9) << load;
        if (load <= 6.0) {
            EXPECT_NEAR(e.state.feedMPerS, 1e-3, 1e-15) << load;
        }
    }
    EXPECT_TRUE(model.equilibrium(13.0).slotFullyOpen);
    EXPECT_FALSE(model.equilibrium(13.0).stalled);
    EXPECT_TRUE(model.equilibrium(20.0).stalled);
    EXPECT_EQ(model.equilibrium(20.0).state.feedMPerS, 0.0);
    // Without a regulator, 6 N leaks 2.36e-5 m^3/s against the pump's 1.77e-5: eq. 21 alone gives
    // 56.588 (1.767e-5 - 2.356e-5) = -3.3e-4 m/s; the carriage stalls instead.
    const HydraulicFeedModel off(HydraulicFeedParams{}, FeedRegulator::Off);
    EXPECT_TRUE(off.equilibrium(6.0).stalled);
    const FeedRun run = simulateFeed(off, FeedLoadProfile::step(0.02, 6.0), {});
    for (const FeedSample& s : run.samples)  // within the stepper's accuracy (1e-9 of the scaled states)
        ASSERT_GE(s.feedMPerS, -1e-6 * 1e-3) << s.timeS;
    EXPECT_NEAR(run.feed.finalValue, 0.0, 1e-12);
    ASSERT_FALSE(run.warnings.empty());
    EXPECT_EQ(run.warnings.front().kind, FeedWarningKind::CarriageStalled);
    EXPECT_EQ(run.warnings.back().kind, FeedWarningKind::FeedOffSet);
    EXPECT_NEAR(run.warnings.back().value, -100.0, 1e-6);
}

// The requirement: steady feed within +-3 % of the set feed for loads 0.5 .. 6 N, settling within
// 3 T_c of each step, no warning; the paper's feed-forward, designed at 3.23 N, misses off its load (the
// figures measured on main before the feedback: 0.847e-3 m/s at 1 N, 2.144e-3 at 6 N).
TEST(FeedFeedback, HoldsTheSetFeedAtEveryLoad) {
    FeedScenario s;
    const double threeTc = 3.0 * deriveFeedQuantities(s.params).cylinderTimeConstantS;
    const std::vector<FeedLoadPoint> points = sweepLoad(s, {0.5, 1.0, 2.0, 3.0, 3.23, 4.0, 5.0, 6.0});
    for (const FeedLoadPoint& p : points) {
        EXPECT_LE(std::abs(p.feedback.deviationPct), kBandPct) << p.loadN;
        EXPECT_LE(p.feedback.feed.settlingS, threeTc) << p.loadN;
        EXPECT_TRUE(p.feedback.feed.settled) << p.loadN;
        EXPECT_TRUE(p.feedback.warnings.empty()) << p.loadN;
        EXPECT_TRUE(p.feedback.hold.withinBand) << p.loadN;
    }
    EXPECT_NEAR(points[1].feedForward.feed.finalValue, 0.847e-3, 0.001e-3);
    EXPECT_NEAR(points[7].feedForward.feed.finalValue, 2.144e-3, 0.001e-3);
    EXPECT_EQ(points[7].feedForward.warnings.back().kind, FeedWarningKind::FeedOffSet);
    EXPECT_NEAR(points[4].feedForward.deviationPct, 0.0, 0.01);  // its design load
    EXPECT_THROW(sweepLoad(s, {}), std::invalid_argument);
    EXPECT_THROW(sweepLoad(s, {-1.0}), std::invalid_argument);
}

// A load changing during the cut: a ramp 1 -> 6 N over 0.2 s and a step sequence up and down. Outside 3 T_c
// after each change the feed stays within +-3 % (the ramp's steady tracking error is about 2 %: the load's
// rate over the loop's integral gain).
TEST(FeedFeedback, HoldsTheSetFeedUnderAChangingLoad) {
    FeedScenario ramp;
    ramp.load.addStep(0.02, 1.0);
    ramp.load.addRamp(0.1, 0.2, 6.0);
    ramp.run.durationS = 0.45;
    const FeedRun r = runFeedScenario(ramp, FeedRegulator::Feedback);
    EXPECT_TRUE(r.hold.withinBand) << r.hold.largestDeviationPct;
    EXPECT_GT(std::abs(r.hold.largestDeviationPct), 1.0);  // the ramp is felt: not a test that cannot fail
    EXPECT_NEAR(r.hold.excludedS, 3.0 * 0.018, 1e-4);
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_FALSE(runFeedScenario(ramp, FeedRegulator::FeedForward).hold.withinBand);

    FeedScenario steps;
    for (const auto& [t, f] :
         std::vector<std::pair<double, double>>{{0.02, 1.0}, {0.1, 3.0}, {0.18, 6.0}, {0.26, 2.0}, {0.34, 0.5}})
        steps.load.addStep(t, f);
    steps.run.durationS = 0.45;
    const FeedRun q = runFeedScenario(steps, FeedRegulator::Feedback);
    EXPECT_TRUE(q.hold.withinBand) << q.hold.largestDeviationPct;
    EXPECT_LE(std::abs(q.deviationPct), kBandPct);
    // Falling by 4 N, the feedback would close the slot further than shut: reported, not hidden.
    ASSERT_FALSE(q.warnings.empty());
    EXPECT_EQ(q.warnings.front().kind, FeedWarningKind::SlotShut);
    EXPECT_GE(q.warnings.front().fromS, 0.26);
}

}  // namespace
}  // namespace tt::core
