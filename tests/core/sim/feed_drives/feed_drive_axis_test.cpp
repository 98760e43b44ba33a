// The feed-drive simulator (paper 002) against closed-form solutions: the velocity loop alone is a
// first-order system, the position loop around a P velocity loop a second-order one; friction, the
// current limit, the encoder and the ball screw each do what their models say.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/sim/feed_drives/feed_drive_axis.h"

namespace tt::core {
namespace {

constexpr double kStepS = 1e-4;

// A frictionless drive with a P velocity loop, a fine encoder and no limits in reach.
FeedDriveAxisConfig linearDrive() {
    FeedDriveAxisConfig c;
    c.coulombFrictionNm = 0.0;
    c.staticFrictionNm = 0.0;
    c.viscousFrictionNmSPerRad = 0.0;
    c.velocityIntegralTimeS = 0.0;
    c.encoderStepMm = 1e-6;
    c.currentLimitA = 1000.0;
    c.commandLimitV = 100.0;
    return c;
}

TEST(FeedDriveAxis, VelocityLoopAloneIsTheFirstOrderLagOfItsAnalyticSolution) {
    // J ω' = Kt Kp (ω_cmd − ω) − b ω: ω(t) = ω∞ (1 − e^(−t/τ)), τ = J / (Kt Kp + b),
    // ω∞ = Kt Kp ω_cmd / (Kt Kp + b). The position loop is opened by commanding the encoder's reading.
    FeedDriveAxisConfig c = linearDrive();
    c.viscousFrictionNmSPerRad = 0.1;
    FeedDriveAxis axis(c, 0.0);
    const double commandV = 0.25;
    const double commandRadPerS = commandV * c.speedPerVoltRadPerSPerV;  // 5 rad/s
    const double ktkp = c.torqueConstantNmPerA * c.velocityGainAPerRadPerS;
    const double tau = c.inertiaKgM2 / (ktkp + c.viscousFrictionNmSPerRad);
    const double final = ktkp * commandRadPerS / (ktkp + c.viscousFrictionNmSPerRad);
    double worst = 0.0;
    for (int n = 1; n <= 600; ++n) {
        axis.step(kStepS, axis.encoderMm(), commandV);
        const double t = n * kStepS;
        worst = std::max(worst, std::abs(axis.speedRadPerS() - final * (1.0 - std::exp(-t / tau))));
    }
    // Explicit Euler on x' = (x∞ − x)/τ stays within (h/τ)/(2e) x∞ of the exact solution; h/τ = 0.0175
    // here (τ = 5.7 ms): 0.32 % of x∞. Tolerance 0.5 %.
    EXPECT_LT(worst, 0.005 * final);
    EXPECT_NEAR(axis.speedRadPerS(), final, 0.005 * final);  // after 10.5 τ
}

TEST(FeedDriveAxis, PositionLoopAroundAPVelocityLoopIsTheSecondOrderOfItsAnalyticSolution) {
    // ω_cmd = Kv (θ_cmd − θ) (Kv in 1/s on the motor angle), i = Kp (ω_cmd − ω), J θ'' = Kt i:
    // θ'' + 2ζω_n θ' + ω_n² θ = ω_n² θ_cmd with ω_n² = Kt Kp Kv / J, 2ζω_n = Kt Kp / J. Step of 0.1 mm.
    FeedDriveAxisConfig c = linearDrive();
    c.inertiaKgM2 = 0.02;
    c.velocityGainAPerRadPerS = 0.3;
    c.positionGainPerS = 30.0;
    const double wn =
        std::sqrt(c.torqueConstantNmPerA * c.velocityGainAPerRadPerS * c.positionGainPerS / c.inertiaKgM2);
    const double zeta = c.torqueConstantNmPerA * c.velocityGainAPerRadPerS / c.inertiaKgM2 / (2.0 * wn);
    ASSERT_LT(zeta, 1.0);  // 0.35: underdamped, 31 % overshoot
    const double wd = wn * std::sqrt(1.0 - zeta * zeta);
    const double stepMm = 0.1;
    FeedDriveAxis axis(c, 0.0);
    double worst = 0.0;
    double peak = 0.0;
    for (int n = 1; n <= 12000; ++n) {
        axis.step(kStepS, stepMm);
        const double t = n * kStepS;
        const double exact =
            stepMm * (1.0 - std::exp(-zeta * wn * t) *
                                (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t)));
        worst = std::max(worst, std::abs(axis.positionMm() - exact));
        peak = std::max(peak, axis.positionMm());
    }
    // Symplectic Euler's phase error after one period (0.31 s) is about (ω_n h)²/24 rad; with the
    // encoder at 1 nm the largest difference stays within 0.5 % of the step. Tolerance 1 %.
    EXPECT_LT(worst, 0.01 * stepMm);
    const double overshoot = std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
    EXPECT_NEAR(peak, stepMm * (1.0 + overshoot), 0.005 * stepMm);
    EXPECT_NEAR(axis.positionMm(), stepMm, 1e-5);  // after 1.2 s: e^(−ζ ω_n t) = 1e-4
}

TEST(FeedDriveAxis, StaticFrictionHoldsTheMotorUntilTheTorquePassesBreakaway) {
    FeedDriveAxisConfig c = linearDrive();
    c.coulombFrictionNm = 0.5;
    c.staticFrictionNm = 1.0;
    c.stribeckSpeedRadPerS = 0.01;  // friction falls to Coulomb at once: the plain Karnopp model
    FeedDriveAxis axis(c, 0.0);
    // Kt Kp ω_cmd = 0.6 * (0.05 V * 20 rad/s/V) = 0.6 N·m < 1 N·m: stuck.
    for (int n = 0; n < 1000; ++n)
        axis.step(kStepS, axis.encoderMm(), 0.05);
    EXPECT_EQ(axis.speedRadPerS(), 0.0);
    EXPECT_EQ(axis.positionMm(), 0.0);
    // 0.1 V: 1.2 N·m > 1 N·m breaks away; then Coulomb 0.5 N·m leaves ω = ω_cmd − 0.5 / (Kt Kp).
    for (int n = 0; n < 2000; ++n)
        axis.step(kStepS, axis.encoderMm(), 0.1);
    EXPECT_NEAR(axis.speedRadPerS(), 2.0 - 0.5 / 0.6, 1e-3);
}

TEST(FeedDriveAxis, CurrentLimitCapsTheAcceleration) {
    FeedDriveAxisConfig c = linearDrive();
    c.currentLimitA = 2.0;
    c.coulombFrictionNm = 0.4;
    c.staticFrictionNm = 0.4;
    FeedDriveAxis axis(c, 0.0);
    axis.step(kStepS, axis.encoderMm(), 5.0);  // 100 rad/s demanded: 60 A wanted
    EXPECT_EQ(axis.currentA(), 2.0);
    for (int n = 0; n < 99; ++n)
        axis.step(kStepS, axis.encoderMm(), 5.0);
    // α = (Kt I_max − T_c) / J = (2 − 0.4) / 0.004 = 400 rad/s²; after 10 ms: 4 rad/s.
    EXPECT_NEAR(axis.speedRadPerS(), 4.0, 1e-9);
}

TEST(FeedDriveAxis, SteadyRampHasTheFollowingErrorOfATypeOneLoopWhateverTheFriction) {
    // A PI velocity loop removes the friction's droop: following error v / Kv (paper's CNC, Kv = 16.7 1/s).
    FeedDriveAxisConfig c;  // preset X drive: Coulomb, static, viscous friction, 1 µm encoder
    const double v = 10.0;  // mm/s
    FeedDriveAxis axis(c, 0.0);
    axis.settleOnRamp(0.0, v);
    double command = 0.0;
    for (int n = 0; n < 5000; ++n) {
        command += v * kStepS;
        axis.step(kStepS, command);
    }
    EXPECT_NEAR(command - axis.positionMm(), v / c.positionGainPerS, 0.002);  // within two encoder steps
    EXPECT_NEAR(axis.speedRadPerS(), motorSpeedRadPerS(c, v), 0.05);
}

TEST(FeedDriveAxis, BallScrewAndEncoderConvertAngleToQuantisedSlidePosition) {
    FeedDriveAxisConfig c;
    c.screwLeadMm = 10.0;
    c.encoderStepMm = 0.001;
    EXPECT_NEAR(motorSpeedRadPerS(c, 10.0), 2.0 * std::numbers::pi, 1e-12);  // one turn per 10 mm
    EXPECT_NEAR(slideSpeedMmPerS(c, 9.0), 14.3239, 1e-4);
    const FeedDriveAxis axis(c, 0.0123456);
    EXPECT_NEAR(axis.positionMm(), 0.0123456, 1e-12);
    EXPECT_NEAR(axis.encoderMm(), 0.012, 1e-12);  // whole steps, rounded down
    const FeedDriveAxis negative(c, -0.0004);
    EXPECT_NEAR(negative.encoderMm(), -0.001, 1e-12);
}

TEST(FeedDriveAxis, RefusesNonPhysicalParameters) {
    FeedDriveAxisConfig c;
    c.screwLeadMm = 0.0;
    EXPECT_THROW(FeedDriveAxis(c, 0.0), std::invalid_argument);
    c = FeedDriveAxisConfig{};
    c.staticFrictionNm = c.coulombFrictionNm / 2.0;
    EXPECT_THROW(validateFeedDriveAxis(c, "Z"), std::invalid_argument);
    c = FeedDriveAxisConfig{};
    c.coulombFrictionNm = 25.0;  // above Kt * I_max = 20 N·m: the drive could never move
    c.staticFrictionNm = 25.0;
    try {
        validateFeedDriveAxis(c, "Z");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("Z: Coulomb friction 25 N·m is not below the torque at the current limit"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace tt::core
