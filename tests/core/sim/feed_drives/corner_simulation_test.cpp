// A corner on the two-axis simulator: the programmed path and its contour error, the paper's control
// interval and cost (paper 002, eqs. 1-4), the pulse fired at Zm0, and the bracketed amplitude search.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/brent_minimum.h"
#include "core/sim/feed_drives/corner_simulation.h"
#include "core/sim/feed_drives/pulse_amplitude_search.h"

namespace tt::core {
namespace {

TEST(CornerPath, ContourErrorIsTheDistanceFromTheTwoMoves) {
    FeedDrivesConfig drives;  // both screws 10 mm: 2π rad/s = 10 mm/s
    const double w = 2.0 * std::acos(-1.0);
    const CornerPath path(drives, {w * 0.5, w * 0.5, 0.5 * w, w});  // (5, 5) mm/s, then (5, 10) mm/s
    EXPECT_NEAR(path.at(-1.0).xMm, -5.0, 1e-12);
    EXPECT_NEAR(path.at(2.0).zMm, 20.0, 1e-12);
    // Behind the corner on the first line: 0; a point off it: its perpendicular distance.
    EXPECT_NEAR(path.distanceMm({-3.0, -3.0}), 0.0, 1e-12);
    EXPECT_NEAR(path.distanceMm({-3.0, -2.0}), 1.0 / std::sqrt(2.0), 1e-12);
    // Beyond the corner the second line (direction (1, 2)/√5) is nearer.
    EXPECT_NEAR(path.distanceMm({1.0, 3.0}), std::abs(2.0 * 1.0 - 3.0) / std::sqrt(5.0), 1e-12);
    // Inside the corner: the corner point itself is the nearest point of both rays.
    EXPECT_NEAR(path.distanceMm({0.1, -0.1}), std::hypot(0.1, 0.1), 1e-12);
}

TEST(CornerPath, RefusesSpeedsOutsideThePapersRange) {
    FeedDrivesConfig drives;
    EXPECT_THROW(CornerPath(drives, {0.4, 1, 1, 1}), std::invalid_argument);
    try {
        CornerPath(drives, {1, 1, 1, 12});
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "Vz2 12 rad/s is outside the motor speeds the pulse is designed for, 0.5 .. 9 rad/s");
    }
}

TEST(CornerCost, CountsOnlyTheIntervalAndWeighsMaxAndMean) {
    CornerCostSettings s;
    s.maxWeight = 0.5;
    s.meanWeight = 2.0;
    CornerCostAccumulator a(s, -1.0, 2.0);
    a.add(-1.5, 9.0);  // before Zn
    a.add(-1.0, 1.0);
    a.add(0.0, 3.0);
    a.add(2.0, 2.0);
    a.add(2.5, 9.0);  // after Zk
    const CornerCost c = a.result();
    EXPECT_DOUBLE_EQ(c.maxErrorMm, 3.0);
    EXPECT_DOUBLE_EQ(c.meanErrorMm, 2.0);
    EXPECT_DOUBLE_EQ(c.cost, 0.5 * 3.0 + 2.0 * 2.0);  // U = k1 e_max + k2 e_mean (eq. 1)
}

TEST(CornerSimulation, AStraightLineHasNoContourErrorBeyondTheEncoder) {
    // Same velocity before and after: a type-1 loop follows the line behind the programmed point.
    const CornerRun run = simulateCorner({}, {}, {4.0, 6.0, 4.0, 6.0}, {}, 0.0);
    EXPECT_LT(run.cost.maxErrorMm, 0.002);  // one or two encoder steps (1 µm)
}

TEST(CornerSimulation, TheIntervalAndThePulseFollowTheToolsPositionAlongZ) {
    FeedDrivesConfig drives;
    CornerCostSettings cost;
    PulseSettings pulse;
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = 1;
    const CornerMove move{3.0, 5.0, 6.0, 5.0};  // X changes speed, Z keeps it
    const CornerRun run = simulateCorner(drives, cost, move, pulse, 0.2, options);
    // Z follows its ramp v / Kv behind the programmed point, i.e. 1 / Kv = 60 ms later: the tool reaches
    // Zm0 = Z1 − Vz1 p_m at p_m before the lagged corner, Zn at t1 before it and Zk at t2 after it
    // (within a step of the sampled trigger and the 1 µm encoder: 0.2 ms at 8 mm/s).
    const double lagS = 1.0 / drives.z.positionGainPerS;
    EXPECT_NEAR(run.pulseStartS, -pulse.leadS + lagS, 3e-4);
    EXPECT_NEAR(run.intervalStartS, -cost.beforeS + lagS, 3e-4);
    EXPECT_NEAR(run.intervalEndS, cost.afterS + lagS, 3e-4);
    // The pulse is on for its duration, 50 ms, then off.
    double onS = 0.0;
    for (double v : run.trace.pulseV)
        if (v != 0.0) {
            EXPECT_EQ(v, 0.2);
            onS += drives.stepS;
        }
    EXPECT_NEAR(onS, pulse.durationS, 1.5 * drives.stepS);
    // A pulse on X moves X only: the Z positions are those of the run without it.
    const CornerRun none = simulateCorner(drives, cost, move, pulse, 0.0, options);
    ASSERT_EQ(none.trace.zMm.size(), run.trace.zMm.size());
    for (std::size_t i = 0; i < run.trace.zMm.size(); ++i)
        ASSERT_EQ(run.trace.zMm[i], none.trace.zMm[i]);
}

TEST(CornerSimulation, RefusesAmplitudesBeyondTheLimitAndStepsAboveATenthOfAMillisecond) {
    EXPECT_THROW(simulateCorner({}, {}, {1, 1, 1, 1}, {}, 0.6), std::invalid_argument);
    FeedDrivesConfig drives;
    drives.stepS = 2e-4;
    EXPECT_THROW(simulateCorner(drives, {}, {1, 1, 1, 1}, {}, 0.0), std::invalid_argument);
}

TEST(BrentMinimum, FindsTheMinimumOfSmoothAndKinkedFunctionsOnTheBracket) {
    int calls = 0;
    const ScalarMinimum q = minimiseBrent(
        [&](double x) {
            ++calls;
            return (x - 2.0) * (x - 2.0) + 1.0;
        },
        0.0, 5.0, 1e-8);
    EXPECT_NEAR(q.x, 2.0, 1e-7);
    EXPECT_NEAR(q.value, 1.0, 1e-12);
    EXPECT_EQ(q.evaluations, calls);
    EXPECT_LT(calls, 15);  // a parabola is found by the first interpolations
    const ScalarMinimum k = minimiseBrent([](double x) { return std::abs(x - 1.0 / 3.0); }, -1.0, 1.0, 1e-6);
    EXPECT_NEAR(k.x, 1.0 / 3.0, 2e-6);
    const ScalarMinimum c = minimiseBrent([](double x) { return std::cos(x); }, 0.0, 6.0, 1e-9);
    EXPECT_NEAR(c.x, std::acos(-1.0), 1e-7);  // tolerance 1e-9/3 + 1.5e-8 |x|
    EXPECT_THROW(minimiseBrent([](double x) { return x; }, 1.0, 1.0, 1e-6), std::invalid_argument);
}

TEST(BrentMinimum, TheGridBracketsTheGlobalMinimumBeforeBrentRefinesIt) {
    // Two wells: a shallow one at −0.3 (value 0.05) and the deep one at 0.35 (0). Brent alone on
    // [−0.5, 0.5] starts at the golden point −0.118 and ends in the shallow well; the grid does not.
    const auto f = [](double x) { return std::min(2.0 * (x + 0.3) * (x + 0.3) + 0.05, 3.0 * (x - 0.35) * (x - 0.35)); };
    const ScalarMinimum g = minimiseOnGrid(f, -0.5, 0.5, 11, 1e-6);
    EXPECT_NEAR(g.x, 0.35, 1e-5);
    const ScalarMinimum b = minimiseBrent(f, -0.5, 0.5, 1e-6);
    EXPECT_NEAR(b.x, -0.3, 1e-5);
}

TEST(PulseSearch, TheBestAmplitudeBeatsItsNeighboursAndNoPulse) {
    const FeedDrivesConfig drives;
    const CornerCostSettings cost;
    const PulseSettings pulse;
    const CornerMove move{7.0, 2.5, 1.5, 7.0};
    const PulseOptimum best = findBestPulse(drives, cost, move, pulse);
    EXPECT_LT(best.with.cost, best.without.cost);
    EXPECT_LE(std::abs(best.amplitudeV), pulse.limitV);
    for (double d : {-0.01, 0.01}) {
        const double a = std::clamp(best.amplitudeV + d, -pulse.limitV, pulse.limitV);
        EXPECT_GE(simulateCorner(drives, cost, move, pulse, a).cost.cost, best.with.cost);
    }
    EXPECT_LE(best.simulations, 42);  // grid and Brent within the 40 allowed, plus the two reported runs
}

}  // namespace
}  // namespace tt::core
