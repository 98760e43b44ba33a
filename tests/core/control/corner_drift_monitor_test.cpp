// The drift monitor of paper 002 ("the difference between the computed error and the expectation of the
// real error over several corrections, misses removed") and the re-identification of the drives' friction,
// inertia and velocity gain from the encoder records of a few corners.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/control/corner_drift_monitor.h"
#include "core/sim/feed_drives/corner_scenario.h"
#include "core/sim/feed_drives/drive_identification.h"

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

TEST(DriftMonitor, FindsWhereTheMachineChangedBeforeJudgingMisses) {
    DriftMonitorSettings s;
    s.windowCorners = 10;
    CornerDriftMonitor m(s);
    // Six corners as predicted, then four 40 % above (a sudden drift), the ninth also hit by a load.
    const double real[] = {0.0100, 0.0101, 0.0099, 0.0100, 0.0102, 0.0098, 0.0140, 0.0141, 0.0300, 0.0139};
    for (double r : real)
        m.add(0.010, r);
    // Hampel's rule over the whole window takes all four drifted corners for misses ...
    const std::vector<bool> whole = m.outlierFlags();
    EXPECT_EQ(std::count(whole.begin(), whole.end(), true), 4);
    // ... the two-segment split puts the change at corner 6 (four corners after it allowed) ...
    EXPECT_EQ(m.changeStart(4), 6);
    // ... and among the corners after it only the load's is a miss.
    const std::vector<bool> after = m.outlierFlagsFrom(6);
    EXPECT_EQ(std::count(after.begin(), after.end(), true), 1);
    EXPECT_TRUE(after[8]);
    // At least minAfter corners stay after the split; a window too short has no split.
    EXPECT_EQ(m.changeStart(7), 3);
    EXPECT_EQ(m.changeStart(10), 0);
}

std::vector<RecordedCorner> recordCorners(const FeedDrivesConfig& machine, int count, unsigned long long seed) {
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = 10;
    std::vector<RecordedCorner> corners;
    for (const CornerMove& m : drawCornerMoves({}, {}, count, seed))
        corners.push_back({m, 0.1, simulateCorner(machine, {}, m, {}, 0.1, options).trace});
    return corners;
}

TEST(DriveIdentification, RecoversAThirtyPercentRiseOfTheZFrictionFromEncoderRecords) {
    const FeedDrivesConfig model;
    const std::vector<RecordedCorner> corners =
        recordCorners(scaledDrives(model, driftFactors(DriveDriftKind::Friction, FeedAxis::Z, 1.3)), 10, 11);
    const DriveEstimate e = identifyDrives(model, {}, {}, {}, corners, {}, 10);
    // The record is what the encoders say (1 µm steps); the Z friction is found within 3 %, the rest left alone.
    EXPECT_NEAR(e.factors.z.friction, 1.3, 0.04);
    EXPECT_NEAR(e.factors.x.friction, 1.0, 0.04);
    for (const DriveFactors& f : {e.factors.x, e.factors.z}) {
        EXPECT_NEAR(f.velocityGain, 1.0, 0.01);
        EXPECT_NEAR(f.inertia, 1.0, 0.05);
    }
    EXPECT_LT(e.zRmsUm, 1.0);
    EXPECT_THROW(identifyDrives(model, {}, {}, {}, {}, {}, 10), std::invalid_argument);
}

TEST(DriveIdentification, TellsAGainDriftFromAnInertiaDriftOnEitherDrive) {
    const FeedDrivesConfig model;
    const struct {
        DriveDriftKind kind;
        FeedAxis axis;
        double factor;
    } cases[] = {{DriveDriftKind::Gain, FeedAxis::Z, 1.5},
                 {DriveDriftKind::Gain, FeedAxis::X, 0.5},
                 {DriveDriftKind::Inertia, FeedAxis::Z, 1.5},
                 {DriveDriftKind::Inertia, FeedAxis::X, 2.5}};
    for (const auto& c : cases) {
        const FeedDrivesFactors truth = driftFactors(c.kind, c.axis, c.factor);
        const DriveEstimate e =
            identifyDrives(model, {}, {}, {}, recordCorners(scaledDrives(model, truth), 6, 11), {}, 10);
        SCOPED_TRACE(std::string(toString(c.kind)) + " " + toString(c.axis) + ": " + describeFactors(e.factors, 3));
        for (FeedAxis axis : {FeedAxis::X, FeedAxis::Z}) {
            // The gain sets the following error (within 0.5 %); the inertia shapes the transients (within 5 %).
            EXPECT_NEAR(axisFactors(e.factors, axis).velocityGain, axisFactors(truth, axis).velocityGain,
                        0.005 * axisFactors(truth, axis).velocityGain);
            EXPECT_NEAR(axisFactors(e.factors, axis).inertia, axisFactors(truth, axis).inertia,
                        0.05 * axisFactors(truth, axis).inertia);
        }
    }
}

TEST(DriveIdentification, NeverTriesAFrictionThatWouldStallTheDrive) {
    // Z: 5 N·m static friction against 24 N·m at the current limit. A bracket up to 20x would pass
    // 4.8x, where the motor can no longer break away; the search stops at 90 % of the peak torque.
    const FeedDrivesConfig model;
    DriveIdentificationSettings s;
    s.frictionMax = 20.0;
    const std::vector<RecordedCorner> corners =
        recordCorners(scaledDrives(model, driftFactors(DriveDriftKind::Friction, FeedAxis::Z, 3.0)), 5, 11);
    const DriveEstimate e = identifyDrives(model, {}, {}, {}, corners, s, 10);
    EXPECT_LT(e.factors.z.friction * model.z.staticFrictionNm,
              0.9 * model.z.torqueConstantNmPerA * model.z.currentLimitA + 1e-9);
    EXPECT_NEAR(e.factors.z.friction, 3.0, 0.1);
}

}  // namespace
}  // namespace tt::core
