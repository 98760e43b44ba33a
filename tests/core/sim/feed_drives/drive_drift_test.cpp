// What drifts in a feed drive (paper 002: "the parameters of the drive systems change with time"):
// friction, the velocity gain (motor speed per volt of velocity command, which the CNC's position loop
// was commissioned with) and the inertia; the factors applied to the drives, refused when out of range
// or when a drive could no longer break away.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sim/feed_drives/drive_drift.h"

namespace tt::core {
namespace {

TEST(DriveDrift, EachKindScalesItsParameterOnItsDriveOnly) {
    const FeedDrivesConfig nominal;
    const FeedDrivesConfig friction = scaledDrives(nominal, driftFactors(DriveDriftKind::Friction, FeedAxis::Z, 1.5));
    EXPECT_DOUBLE_EQ(friction.z.coulombFrictionNm, 1.5 * nominal.z.coulombFrictionNm);
    EXPECT_DOUBLE_EQ(friction.z.staticFrictionNm, 1.5 * nominal.z.staticFrictionNm);
    EXPECT_DOUBLE_EQ(friction.z.viscousFrictionNmSPerRad, 1.5 * nominal.z.viscousFrictionNmSPerRad);
    EXPECT_DOUBLE_EQ(friction.x.coulombFrictionNm, nominal.x.coulombFrictionNm);
    const FeedDrivesConfig gain = scaledDrives(nominal, driftFactors(DriveDriftKind::Gain, FeedAxis::X, 0.5));
    EXPECT_DOUBLE_EQ(gain.x.velocityGainFactor, 0.5);
    EXPECT_DOUBLE_EQ(gain.x.speedPerVoltRadPerSPerV, nominal.x.speedPerVoltRadPerSPerV);  // the CNC's scaling
    EXPECT_DOUBLE_EQ(gain.z.velocityGainFactor, 1.0);
    const FeedDrivesConfig inertia = scaledDrives(nominal, driftFactors(DriveDriftKind::Inertia, FeedAxis::Z, 3.0));
    EXPECT_DOUBLE_EQ(inertia.z.inertiaKgM2, 3.0 * nominal.z.inertiaKgM2);
    EXPECT_DOUBLE_EQ(inertia.x.inertiaKgM2, nominal.x.inertiaKgM2);
    for (DriveDriftKind k : {DriveDriftKind::Friction, DriveDriftKind::Gain, DriveDriftKind::Inertia})
        EXPECT_EQ(driveDriftKindFromString(toString(k)), k);
}

TEST(DriveDrift, RefusesFactorsOutsideTheRangeAndDrivesThatCouldNotBreakAway) {
    try {
        driftFactors(DriveDriftKind::Gain, FeedAxis::Z, 3.5);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "drift factor 3.5 is outside 0.5 .. 3");
    }
    EXPECT_THROW(driftFactors(DriveDriftKind::Inertia, FeedAxis::X, 0.4), std::invalid_argument);
    EXPECT_THROW(driveDriftKindFromString("load"), std::invalid_argument);
    // Z of 10 N·m static friction against Kt·I_max = 24 N·m: three times that could never break away.
    FeedDrivesConfig sticky;
    sticky.z.staticFrictionNm = 10.0;
    try {
        scaledDrives(sticky, driftFactors(DriveDriftKind::Friction, FeedAxis::Z, 3.0));
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(),
                     "Z: static friction 30 N·m is not below the torque at the current limit (24 N·m): the motor "
                     "could never break away");
    }
}

TEST(DriveDrift, AVelocityGainDriftChangesTheFollowingErrorAsTheCncsLoopGainWould) {
    // The CNC scales its output by the commissioned speed per volt; the drive makes g times that speed.
    // On a ramp at v the PI velocity loop follows exactly, so the following error is v / (Kv g): the
    // drift is a change of the position loop's effective gain (nominal 10 / 16.7 = 0.599 mm at 10 mm/s).
    for (double g : {0.5, 1.0, 1.5, 3.0}) {
        FeedDriveAxisConfig c;
        c.velocityGainFactor = g;
        FeedDriveAxis axis(c, 0.0);
        const double v = 10.0;
        const double dt = 1e-4;
        double command = 0.0;
        for (int n = 0; n < 20000; ++n) {  // 2 s: the start-up transient has died out
            command += v * dt;
            axis.step(dt, command);
        }
        // Within two encoder steps (it rounds down, and the command is held for a step).
        EXPECT_NEAR(command - axis.positionMm(), v / (c.positionGainPerS * g), 0.002) << "g = " << g;
        EXPECT_NEAR(axis.speedRadPerS(), motorSpeedRadPerS(c, v), 0.05);
    }
    // settleOnRamp puts the drive in that same state.
    FeedDriveAxisConfig c;
    c.velocityGainFactor = 1.5;
    FeedDriveAxis settled(c, 0.0);
    settled.settleOnRamp(5.0, 10.0);
    EXPECT_NEAR(5.0 - settled.positionMm(), 10.0 / (c.positionGainPerS * 1.5), 1e-12);
}

TEST(DriveDrift, DescribesFactorsForTheOperator) {
    FeedDrivesFactors f;
    f.z.velocityGain = 1.5;
    EXPECT_EQ(describeFactors(f, 2),
              "X friction x1.00, inertia x1.00, gain x1.00; Z friction x1.00, inertia x1.00, gain x1.50");
}

}  // namespace
}  // namespace tt::core
