// The drift monitor of paper 002 ("the difference between the computed error and the expectation of the
// real error over several corrections, misses removed") and the re-identification of the drives' friction.
#include <gtest/gtest.h>

#include "core/control/corner_drift_monitor.h"
#include "core/sim/feed_drives/corner_scenario.h"
#include "core/sim/feed_drives/friction_identification.h"

namespace tt::core {
namespace {

TEST(DriftMonitor, MedianAndHampelRule) {
    EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
    // Residuals 1.0 ± 0.1 and one at 3: median 1.0, MAD 0.1, limit 3 × 1.4826 × 0.1 = 0.445.
    const std::vector<int> out = hampelOutliers({1.0, 1.1, 0.9, 1.0, 3.0, 1.05, 0.95}, 3.0);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0], 4);
    EXPECT_TRUE(hampelOutliers({2.0, 2.0, 2.0, 5.0}, 3.0).empty());  // MAD 0: nothing can be judged
}

TEST(DriftMonitor, WaitsForAFullWindowIgnoresMissesAndTriggersAboveTheThreshold) {
    DriftMonitorSettings s;
    s.windowCorners = 5;
    s.thresholdFraction = 0.05;
    CornerDriftMonitor m(s);
    for (int i = 0; i < 4; ++i)
        m.add(0.010, 0.0112);  // 12 % above, but the window is not full yet
    EXPECT_FALSE(m.check().retrain);
    m.add(0.010, 0.0100);
    m.add(0.010, 0.0101);
    m.add(0.010, 0.0099);
    m.add(0.010, 0.0100);
    m.add(0.010, 0.0300);  // a miss: a hard spot tripled the error
    DriftCheck c = m.check();
    EXPECT_EQ(c.corners, 5);
    EXPECT_EQ(c.outliers, 1);
    EXPECT_NEAR(c.differenceFraction, 0.0, 1e-9);
    EXPECT_FALSE(c.retrain);
    for (int i = 0; i < 5; ++i)
        m.add(0.010, 0.0107 + 0.0001 * (i % 2));  // 7 .. 8 % above: drift
    c = m.check();
    EXPECT_TRUE(c.retrain);
    EXPECT_NEAR(c.differenceFraction, 0.074, 1e-9);
    EXPECT_NE(c.reason.find("7.4 % above the predicted 10 µm (threshold 5.0 %)"), std::string::npos) << c.reason;
    m.clear();
    EXPECT_EQ(m.size(), 0);
    EXPECT_THROW(m.add(std::nan(""), 0.01), std::invalid_argument);
    s.windowCorners = 2;
    EXPECT_THROW(CornerDriftMonitor{s}, std::invalid_argument);
}

TEST(FrictionIdentification, RecoversAThirtyPercentRiseOfTheZFrictionFromEncoderRecords) {
    FeedDrivesConfig model;
    FeedDrivesConfig machine = model;
    scaleFriction(machine, FeedAxis::Z, 1.3);
    const CornerCostSettings cost;
    const PulseSettings pulse;
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = 10;
    std::vector<RecordedCorner> corners;
    for (const CornerMove& m : drawCornerMoves({}, {}, 10, 11))
        corners.push_back({m, 0.1, simulateCorner(machine, cost, m, pulse, 0.1, options).trace});
    const FrictionEstimate e = identifyFriction(model, cost, pulse, corners, 0.3, 3.0, 10);
    // The record is what the encoders say (1 µm steps); the Z friction is found within 3 %, X left alone.
    EXPECT_NEAR(e.zFactor, 1.3, 0.04);
    EXPECT_NEAR(e.xFactor, 1.0, 0.04);
    EXPECT_LT(e.zRmsUm, 1.0);
    EXPECT_THROW(identifyFriction(model, cost, pulse, {}, 0.3, 3.0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
