// Simulator physics of boring (paper 001) and the headline result: in-process compensation from
// the current with dither and from the probe mandrel cuts the bore error of a slender bar by ≥ 80 %.
#include <gtest/gtest.h>

#include <cmath>

#include "core/control/in_process_compensation.h"
#include "core/run/boring_run.h"
#include "core/run/boring_simulation.h"
#include "core/sim/boring/cross_feed_drive.h"
#include "core/sim/boring/dither_profile.h"
#include "core/sim/boring/inductive_probe.h"
#include "core/sim/rigs/probe_calibration_rig.h"
#include "support/heavy_scenario.h"

namespace tt::core {
namespace {

TEST(DitherProfile, TrapezoidStrokesBetweenMinusAndPlusAmplitude) {
    const DitherProfile p({0.01, 0.5, 0.6});
    // Stroke 2A = V (t_a + t_c) with t_a = 0.05 s, t_c = 0.15 s: V = 0.02 / 0.2 = 0.1 mm/s.
    EXPECT_NEAR(p.plateauSpeedMmPerS(), 0.1, 1e-12);
    EXPECT_NEAR(p.plateauDurationS(), 0.15, 1e-12);
    double lo = 0.0, hi = 0.0;
    for (double t = 0.0; t < 5.0; t += 0.001) {
        const DitherState s = p.at(t);
        lo = std::min(lo, s.positionMm);
        hi = std::max(hi, s.positionMm);
        EXPECT_LE(std::abs(s.velocityMmPerS), 0.1 + 1e-12);
    }
    EXPECT_NEAR(lo, -0.01, 1e-6);
    EXPECT_NEAR(hi, 0.01, 1e-6);
    // Periodic after the first half stroke (0.15 s: t_a + A / V = 0.05 + 0.1).
    EXPECT_NEAR(p.at(1.234).positionMm, p.at(1.734).positionMm, 1e-12);
    EXPECT_NEAR(p.at(0.15 + 0.1).velocityMmPerS, 0.1, 1e-12);               // mid forward stroke
    EXPECT_NEAR(p.at(0.15 + 0.02).accelerationMmPerS2, 2.0, 1e-12);         // V / t_a
    EXPECT_THROW(DitherProfile({0.001, 0.5, 0.6}), std::invalid_argument);  // below 0.005 mm
    EXPECT_THROW(DitherProfile({0.01, 3.0, 0.6}), std::invalid_argument);   // above 2 s
}

TEST(CrossFeedDrive, CurrentAtConstantVelocityIsFrictionPlusLoadOverKp) {
    CrossFeedDriveConfig c;
    c.currentNoiseA = 0.0;
    CrossFeedDrive drive(c, 1);
    // Command 0.1 mm/s outwards against P = 300 N (external force −300 N) for 2 s.
    const double dt = 1e-4;
    for (double t = dt; t <= 2.0; t += dt)
        drive.step(dt, {0.1 * t, 0.1, 0.0}, -300.0);
    // F = F_c + c V + P = 975 + 50 · 0.1 + 300 = 1280 N; I = 1280 / 150 = 8.533 A.
    EXPECT_NEAR(drive.slideVelocityMmPerS(), 0.1, 1e-4);
    EXPECT_NEAR(drive.currentA(), 1280.0 / 150.0, 0.01);
}

TEST(CrossFeedDrive, SlideStaysStuckWhenTheCommandCannotBreakStaticFriction) {
    CrossFeedDrive drive(CrossFeedDriveConfig{}, 1);
    // 1 µm of motor motion through 5e5 N/mm is 500 N < 1070 N breakaway.
    for (int i = 0; i < 10000; ++i)
        drive.step(1e-4, {0.001, 0.0, 0.0}, 0.0);
    EXPECT_DOUBLE_EQ(drive.slidePositionMm(), 0.0);
    EXPECT_NEAR(drive.motorForceN(), 500.0, 1e-9);
}

TEST(InductiveProbe, DifferentialBridgeIsSymmetricAndRatiometric) {
    InductiveProbeConfig c;
    c.noiseRms = 0.0;
    InductiveProbe probe(c, 1);
    // Odd characteristic r(u) = 0.8 u + 0.15 u³: code(δ) + code(−δ) = full scale.
    EXPECT_NEAR(probe.staticCode(0.2) + probe.staticCode(-0.2), 4095.0, 1e-9);
    EXPECT_NEAR(probe.staticCode(0.0), 2047.5, 1e-9);
    // Sensor at 0.9 L sees w(0.9 L) / w(L) = 0.81 · 2.1 / 2 = 0.8505 of the tip deflection.
    EXPECT_NEAR(sensorToTipRatio(0.9), 0.8505, 1e-12);
    EXPECT_NEAR(sensorToTipRatio(0.5), 0.3125, 1e-12);
    // The supply swings ±5 % over 7 s; the ratiometric ADC gives the same code throughout.
    probe.settle(0.15, 0.0);
    const auto a = probe.convert(0.0);
    const auto b = probe.convert(1.75);  // supply at +5 %
    const auto d = probe.convert(5.25);  // supply at −5 %
    EXPECT_EQ(a[0], b[0]);
    EXPECT_EQ(a[0], d[0]);
    EXPECT_EQ(a[0], static_cast<int>(std::lround(probe.staticCode(0.15))));
    // Second plane sees 1 % cross-talk of the first: u = 0.01 · 0.15 · 0.8505 / 0.5.
    EXPECT_EQ(a[1],
              static_cast<int>(std::lround((1.0 + probe.bridgeRatio(0.01 * 0.15 * 0.8505 / 0.5)) / 2.0 * 4095.0)));
    InductiveProbeConfig bad = c;
    bad.bridgeCoefficients = {0.0, 1.0};
    EXPECT_THROW(InductiveProbe(bad, 1), std::invalid_argument);  // degree 1: not 2..4
    bad = c;
    bad.adcBits = 18;
    EXPECT_THROW(InductiveProbe(bad, 1), std::invalid_argument);
}

TEST(ProbeCalibrationRig, LinearisesTheSimulatedMandrelWithDegreeThree) {
    InductiveProbe probe(InductiveProbeConfig{}, 5);
    ProbeCalibrationRig rig(probe, 0, 1.0, 0.3, 6);
    const auto points = rig.sweep(ProbeCalibrationConfig{});
    ASSERT_EQ(points.size(), 21u);
    const Linearisation lin = linearise(points, 12, kAutoDegree);
    EXPECT_EQ(lin.fit.degree, 3) << lin.fit.choiceReason;  // the bridge is an odd cubic in the gap
    EXPECT_LT(lin.maxTableErrorUm, 2.0);
}

TEST(InProcessCompensation, HoldsTheLastOffsetWhileTheDriveReadoutIsDownAndResumes) {
    const BoringScenario s = test::heavyBoring();
    SimulatedBoringPass pass(s, BoringMethod::Current, false);
    const std::unique_ptr<BoringRun> run = buildBoringRun(boringChoices(s, BoringMethod::Current), pass);
    auto runFor = [&](double seconds) {
        CompensationCycle last;
        for (int i = 0; i < static_cast<int>(seconds / s.plcCycleS); ++i)
            last = *run->cycle().compensation;
        return last;
    };
    runFor(30.0);  // into the bore, compensating
    const double before = run->offsetMm();
    ASSERT_GT(before, 0.08);
    pass.overrideSourceHealth(DeviceHealth{DeviceState::Error, "no answer from the drive for 0.5 s"});
    const CompensationCycle silent = runFor(5.0);
    EXPECT_TRUE(silent.step.holding);
    EXPECT_EQ(silent.reading.problem, ReadingProblem::SourceNotReady);
    EXPECT_EQ(silent.reading.sourceHealth.message, "no answer from the drive for 0.5 s");
    EXPECT_DOUBLE_EQ(run->offsetMm(), before);
    pass.overrideSourceHealth(std::nullopt);
    const CompensationCycle back = runFor(5.0);
    EXPECT_FALSE(back.step.holding) << toString(back.reading.problem);
    // Meanwhile the force grew along the bore; the offset follows it again.
    EXPECT_NEAR(run->offsetMm(), -pass.machine().state().tipDeflectionXmm, 0.01);
}

class HeavyBoring : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const BoringScenario s = test::heavyBoring();
        none = new BoringResult(runBoring(s, BoringMethod::None));
        current = new BoringResult(runBoring(s, BoringMethod::Current));
        probe = new BoringResult(runBoring(s, BoringMethod::Probe));
    }
    static void TearDownTestSuite() {
        delete none;
        delete current;
        delete probe;
    }
    static BoringResult* none;
    static BoringResult* current;
    static BoringResult* probe;
};
BoringResult* HeavyBoring::none = nullptr;
BoringResult* HeavyBoring::current = nullptr;
BoringResult* HeavyBoring::probe = nullptr;

TEST_F(HeavyBoring, UncompensatedSlenderBarLeavesTheBoreUndersize) {
    // k = 0.97 · 2474 N/mm, P ≈ 210 .. 380 N: deflection 0.09 .. 0.16 mm, twice that on the diameter.
    EXPECT_GT(none->deflectionMaxMm, 0.12);
    EXPECT_LT(none->deflectionMaxMm, 0.2);
    EXPECT_NEAR(none->boreErrorMaxMm, 2.0 * none->deflectionMaxMm, 0.02);
    EXPECT_FALSE(none->forceEstimateErrorPct);
}

TEST_F(HeavyBoring, CurrentWithDitherCutsTheBoreErrorByAtLeast80Percent) {
    // Coulomb friction (975 N) is three times the mean cutting force of the compensated bore
    // (issue 6: "Coulomb friction three times the cutting force").
    const double coulomb = test::heavyBoring().drive.coulombFrictionN;
    EXPECT_GT(coulomb / current->forceMeanN, 2.9);
    EXPECT_LT(coulomb / current->forceMeanN, 3.1);
    EXPECT_LE(current->boreErrorMaxMm, 0.2 * none->boreErrorMaxMm)
        << current->boreErrorMaxMm << " vs " << none->boreErrorMaxMm;
    ASSERT_TRUE(current->forceEstimateErrorPct);
    EXPECT_LT(*current->forceEstimateErrorPct, 10.0);
    EXPECT_GT(current->estimates, 1000);
}

TEST_F(HeavyBoring, ProbeMandrelCutsTheBoreErrorByAtLeast80Percent) {
    EXPECT_LE(probe->boreErrorMaxMm, 0.2 * none->boreErrorMaxMm)
        << probe->boreErrorMaxMm << " vs " << none->boreErrorMaxMm;
    ASSERT_TRUE(probe->forceEstimateErrorPct);
    EXPECT_LT(*probe->forceEstimateErrorPct, 10.0);
    ASSERT_TRUE(probe->calibration);
    EXPECT_EQ(probe->calibration->degree, 3);
}

TEST_F(HeavyBoring, RunsAreDeterministicForASeed) {
    const BoringResult again = runBoring(test::heavyBoring(), BoringMethod::None);
    EXPECT_DOUBLE_EQ(again.boreErrorMaxMm, none->boreErrorMaxMm);
    EXPECT_DOUBLE_EQ(again.boreErrorRmsMm, none->boreErrorRmsMm);
}

}  // namespace
}  // namespace tt::core
