// The regulator's design aids (issue 16, item 3): the xi sweep (the paper: below 1 the spool oscillates,
// slightly above 1 is recommended), the gain sweep, the parameters' sensitivity, and the step metrics
// (settling time with the paper's t_c = 3T rule, overshoot).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/sim/hydraulic/feed_study.h"
#include "core/sim/hydraulic/step_metrics.h"

namespace tt::core {
namespace {

constexpr double kPaperLoadN = 3.23;

FeedScenario paperScenario() {
    FeedScenario s;
    s.load = FeedLoadProfile::step(0.02, kPaperLoadN);
    return s;
}

// "Done when": the xi sweep shows oscillation for xi < 1 and none above, with settling times reported.
TEST(FeedSweep, DampingRatioBelowOneOscillatesAndAboveDoesNot) {
    const FeedScenario scenario = paperScenario();
    const std::vector<double> values = defaultSweepValues(FeedSweepKind::DampingRatio, scenario);
    EXPECT_EQ(values, (std::vector<double>{0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.5, 2.0}));
    int reported = 0;
    const std::vector<FeedSweepPoint> points =
        sweepFeed(scenario, FeedSweepKind::DampingRatio, values, FeedRegulator::FeedForward, [&](int done, int total) {
            EXPECT_EQ(done, reported + 1);
            EXPECT_EQ(total, 8);
            reported = done;
        });
    ASSERT_EQ(points.size(), values.size());
    EXPECT_EQ(reported, 8);
    double previousSettling = 0.0;
    for (const FeedSweepPoint& p : points) {
        EXPECT_EQ(p.oscillates, p.value < 1.0)
            << "xi = " << p.value << ": opening overshoot " << p.run.opening.overshootPct << " %";
        EXPECT_TRUE(p.stable);
        EXPECT_TRUE(p.run.feed.settled);
        EXPECT_GT(p.run.feed.settlingS, 0.03) << p.value;
        EXPECT_LT(p.run.feed.settlingS, 0.1) << p.value;
        EXPECT_NEAR(p.run.feed.finalValue, 1e-3, 1e-6);  // xi moves the transient, not the steady feed
        if (p.value >= 1.0) {
            // Above critical damping the slower spool only lengthens the transient: xi slightly above 1 is
            // near the shortest one without oscillation, as the paper recommends.
            EXPECT_GT(p.run.feed.settlingS, previousSettling) << p.value;
            previousSettling = p.run.feed.settlingS;
        }
    }
    // The spool's swing shrinks as xi grows towards 1 (xi = 0.2: about half the opening).
    EXPECT_GT(points[0].run.opening.overshootPct, 30.0);
    for (std::size_t k = 1; k < 4; ++k)
        EXPECT_LT(points[k].run.opening.overshootPct, points[k - 1].run.opening.overshootPct);
}

// The gain sweep on the paper's chain (no lap, no bias, y = 0): the regulator's flow goes with the
// square of the gain, so the steady feed is u = 1 - b + b (K/K*)^2 (b = 0.7178) until the slot is
// fully open (above 1.929 K*).
TEST(FeedSweep, GainSweepFollowsTheSquareLawUntilTheSlotIsFullyOpen) {
    const FeedScenario scenario = paperScenario();
    const std::vector<double> values = defaultSweepValues(FeedSweepKind::AmplifierGain, scenario);
    ASSERT_EQ(values.size(), 8u);
    const double design = designAmplifierGain(scenario.params, kPaperLoadN);
    EXPECT_NEAR(values[4], design, 1e-9);
    const std::vector<FeedSweepPoint> points = sweepFeed(scenario, FeedSweepKind::AmplifierGain, values);
    const double b = 0.717823;  // k_0 alpha_0 / S
    for (const FeedSweepPoint& p : points) {
        const double ratio = p.value / design;
        if (ratio <= 1.9) {
            EXPECT_NEAR(p.run.feed.finalValue / 1e-3, 1.0 - b + b * ratio * ratio, 1e-4) << ratio;
            EXPECT_FALSE(p.run.slotFullyOpen);
        } else {
            EXPECT_TRUE(p.run.slotFullyOpen) << ratio;
        }
        EXPECT_TRUE(p.stable);  // no loop: no gain destabilises the chain
    }
    EXPECT_THROW(sweepFeed(scenario, FeedSweepKind::AmplifierGain, {-1.0}), std::invalid_argument);
    EXPECT_THROW(sweepFeed(scenario, FeedSweepKind::DampingRatio, {}), std::invalid_argument);
    EXPECT_THROW(feedSweepKindFromString("mass"), std::invalid_argument);
    EXPECT_EQ(feedSweepKindFromString("xi"), FeedSweepKind::DampingRatio);
}

// With the sensed force following the chip (preset hydraulic-feed-chip, y = 0.6) the gains beyond the
// stability boundary (1.022 x the design gain) run away to the fully open slot and are marked unstable.
TEST(FeedSweep, GainsBeyondTheBoundaryRunAway) {
    FeedScenario scenario = paperScenario();
    scenario.params.feedExponent = 0.6;
    scenario.run.durationS = 2.0;
    scenario.run.sampleS = 1e-3;
    const double design = designAmplifierGain(scenario.params, kPaperLoadN);
    const std::vector<FeedSweepPoint> points =
        sweepFeed(scenario, FeedSweepKind::AmplifierGain, {0.5 * design, 1.0 * design, 1.25 * design});
    EXPECT_TRUE(points[0].stable);
    EXPECT_TRUE(points[1].stable);
    EXPECT_FALSE(points[2].stable);
    EXPECT_FALSE(points[1].run.slotFullyOpen);
    EXPECT_NEAR(points[1].run.feed.finalValue, 1e-3, 1e-6);
    EXPECT_TRUE(points[2].run.slotFullyOpen);
}

TEST(FeedSweep, CanBeCancelled) {
    EXPECT_THROW(sweepFeed(paperScenario(), FeedSweepKind::DampingRatio, {0.5, 1.0}, FeedRegulator::FeedForward, {},
                           [] { return true; }),
                 FeedSimulationCancelled);
}

// Which 10 % change moves the steady feed most. With the regulator on, the piston diameter: the pump's
// flow scales with F = pi D^2/4 but the regulator's does not, so u = 1 + b (1 - 1/f)/f with f = 1.21 or
// 0.81: +10.296 % and -20.787 %. Without it, k_y moves u = 1 - b by -/+ b/10: +-25.44 %.
TEST(FeedSensitivityTest, PistonDiameterMovesTheRegulatedFeedMost) {
    const std::vector<FeedSensitivity> s = feedSensitivity(HydraulicFeedParams{}, kPaperLoadN);
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(s.front().key, "cylinder.piston_diameter_m");
    const double b = 0.717823;
    EXPECT_NEAR(s.front().onPlusPct, 100.0 * b * (1.0 - 1.0 / 1.21) / 1.21, 1e-3);
    EXPECT_NEAR(s.front().onMinusPct, 100.0 * b * (1.0 - 1.0 / 0.81) / 0.81, 1e-3);
    for (const FeedSensitivity& e : s) {
        EXPECT_NE(e.key, "cylinder.set_feed_m_per_s");
        EXPECT_NE(e.nominal, 0.0);
        if (e.key == "cylinder.leakage_m3_per_s_pa") {
            EXPECT_NEAR(e.offPlusPct, -100.0 * 0.1 * b / (1.0 - b), 0.01);
            EXPECT_NEAR(e.offMinusPct, 100.0 * 0.1 * b / (1.0 - b), 0.01);
        }
        if (e.key == "cylinder.mass_kg" || e.key == "spool.damping_ratio") {
            EXPECT_EQ(e.onPlusPct, 0.0);  // dynamics only
        }
    }
    EXPECT_THROW(feedSensitivity(HydraulicFeedParams{}, kPaperLoadN, 0.0), std::invalid_argument);
}

// A first-order response settles into the 5 % band at 3 T (the paper's t_c = 3T) with no overshoot.
TEST(StepMetricsTest, FirstOrderSettlesAtThreeTimeConstants) {
    std::vector<double> t, v;
    for (int k = 0; k <= 4000; ++k) {
        t.push_back(k * 1e-4);
        v.push_back(t.back() < 0.05 ? 1.0 : 0.3 + 0.7 * std::exp(-(t.back() - 0.05) / 0.018));
    }
    const StepMetrics m = stepMetrics(t, v, 0.05);
    EXPECT_NEAR(m.settlingS, 3.0 * 0.018, 2e-4);  // the final sample is 0.3 + 2e-8 of the true final value
    EXPECT_NEAR(m.peakDeviation, 0.7, 1e-6);
    EXPECT_EQ(m.overshootPct, 0.0);
    EXPECT_TRUE(m.settled);
}

// A response that does not move (a load step of 0 N) has no transient, whatever its rounding noise.
TEST(StepMetricsTest, RoundingNoiseIsNoTransient) {
    const std::vector<double> t = {0.0, 0.1, 0.2, 0.3};
    const StepMetrics m = stepMetrics(t, {1e-3, 1e-3 + 3e-18, 1e-3 - 2e-18, 1e-3}, 0.05);
    EXPECT_EQ(m.peakDeviation, 0.0);
    EXPECT_EQ(m.settlingS, 0.0);
    EXPECT_EQ(m.overshootPct, 0.0);
    EXPECT_TRUE(m.settled);
}

// An underdamped second-order step overshoots by exp(-pi xi / sqrt(1 - xi^2)): 16.3 % at xi = 0.5.
TEST(StepMetricsTest, SecondOrderOvershoot) {
    const double xi = 0.5, tz = 0.01;
    const double tDecay = tz / xi, w = std::sqrt(1.0 - xi * xi) / tz;
    std::vector<double> t, v;
    for (int k = 0; k <= 20000; ++k) {
        t.push_back(k * 2e-5);
        v.push_back(1.0 -
                    std::exp(-t.back() / tDecay) * (std::cos(w * t.back()) + std::sin(w * t.back()) / (w * tDecay)));
    }
    const StepMetrics m = stepMetrics(t, v, 0.0);
    EXPECT_NEAR(m.overshootPct, 100.0 * std::exp(-std::numbers::pi * xi / std::sqrt(1.0 - xi * xi)), 0.01);
    EXPECT_NEAR(m.peakDeviation, -1.0, 1e-8);                     // the last sample is 2e-9 short of the final value
    EXPECT_THROW(stepMetrics(t, v, 1.0), std::invalid_argument);  // no samples after the event
    EXPECT_THROW(stepMetrics(t, {1.0}, 0.0), std::invalid_argument);
    EXPECT_THROW(stepMetrics(t, v, 0.0, 1.5), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
