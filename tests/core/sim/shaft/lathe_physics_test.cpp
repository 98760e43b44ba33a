// The physics of the lathe simulator: the shaft on elastic centres, the Kienzle-type radial force and
// the self-consistent cut, checked against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/sim/shaft/lathe_cutting_force.h"
#include "core/sim/shaft/lathe_shaft_beam.h"
#include "core/sim/shaft/lathe_simulator.h"

namespace tt::core {
namespace {

constexpr double kE = 210000.0;  // steel, N/mm²

double secondMoment(double d) {
    return std::numbers::pi * std::pow(d, 4) / 64.0;
}

/// Deflection under a point load P at x of a uniform beam on two springs (simply supported beam:
/// Timoshenko & Gere, "Mechanics of Materials", table of beam deflections, w = P a² b² / (3 E I L);
/// plus the rigid-body motion of the beam on the springs).
double closedFormCompliance(double x, double length, double d, double kA, double kB) {
    const double xi = x / length;
    return (1 - xi) * (1 - xi) / kA + xi * xi / kB +
           x * x * (length - x) * (length - x) / (3 * kE * secondMoment(d) * length);
}

TEST(LatheShaftBeam, UniformShaftMatchesTheClosedFormAtEveryNode) {
    const double length = 325.0, d = 27.0, kA = 32000.0, kB = 10500.0;
    const LatheShaftBeam beam(length, kE, kA, kB, 65);
    const std::vector<double> diameters(65, d);
    for (int node = 0; node <= 65; ++node) {
        const double x = beam.nodeXMm(node);
        const double fe = beam.deflectionMm(node, 1.0, diameters)(node);
        EXPECT_NEAR(fe / closedFormCompliance(x, length, d, kA, kB), 1.0, 1e-9) << "x = " << x;
    }
    // Mid-span of a 27 mm shaft: L³/(48 E I) = 325³ / (48 · 210000 · 26087) = 1.3055e-4 mm/N (hand computed).
    const double rigidSupports =
        LatheShaftBeam(length, kE, 1e12, 1e12, 130).deflectionMm(65, 1.0, std::vector<double>(130, d))(65);
    EXPECT_NEAR(rigidSupports, 1.3055e-4, 0.0005e-4);
}

TEST(LatheShaftBeam, SteppedShaftLiesBetweenTheFinishedAndTheBlankShaft) {
    const LatheShaftBeam beam(325.0, kE, 30000.0, 15000.0, 130);
    const auto stepped = beam.cuttingComplianceMmPerN(27.0, 28.2, true);
    const auto thin = beam.cuttingComplianceMmPerN(27.0, 27.0, true);
    const auto thick = beam.cuttingComplianceMmPerN(28.2, 28.2, true);
    for (std::size_t i = 1; i + 1 < stepped.size(); ++i) {
        EXPECT_LT(stepped[i], thin[i]);
        EXPECT_GT(stepped[i], thick[i]);
    }
    // At the ends the whole shaft is blank (tailstock end: cut starts) or finished (headstock end).
    EXPECT_NEAR(stepped.back(), thick.back(), 1e-12);
    EXPECT_NEAR(stepped.front(), thin.front(), 1e-12);
}

TEST(LatheShaftBeam, RefusesNonPhysicalInput) {
    EXPECT_THROW(LatheShaftBeam(0.0, kE, 1.0, 1.0, 10), std::invalid_argument);
    EXPECT_THROW(LatheShaftBeam(325.0, kE, -1.0, 1.0, 10), std::invalid_argument);
    EXPECT_THROW(LatheShaftBeam(325.0, kE, 1.0, 1.0, 1), std::invalid_argument);
    const LatheShaftBeam beam(325.0, kE, 1.0, 1.0, 10);
    EXPECT_THROW(beam.deflectionMm(11, 1.0, std::vector<double>(10, 27.0)), std::invalid_argument);
    EXPECT_THROW(beam.deflectionMm(5, 1.0, std::vector<double>(9, 27.0)), std::invalid_argument);
}

TEST(LatheCuttingForce, KienzleRadialForceAtThePapersCut) {
    LatheForceModel model;  // k = 1100 N/mm², m = 0.5, κ = 90°, v_ref = 100 m/min, s = 0.1
    LatheCutting cut;       // a = 0.6, f = 0.25, v = 46.3
    const LatheCuttingForce force(model, cut);
    // By hand: 1100 · 0.6 · 0.25^0.5 · (46.3/100)^-0.1 = 330 · 1.08005 = 356.42 N
    EXPECT_NEAR(force.radialForceN(0.6), 356.42, 0.01);
    EXPECT_NEAR(force.radialForceN(1.2), 2.0 * force.radialForceN(0.6), 1e-9) << "proportional to the depth";
    EXPECT_EQ(force.radialForceN(-0.1), 0.0);
    model.leadAngleDeg = 45.0;  // b = a / sin κ grows, h = f sin κ shrinks: F ∝ (sin κ)^(-m)
    EXPECT_NEAR(LatheCuttingForce(model, cut).radialForceN(0.6) / force.radialForceN(0.6),
                std::pow(std::sin(std::numbers::pi / 4), -0.5), 1e-12);
    model.exponent = 1.0;
    EXPECT_THROW(LatheCuttingForce(model, cut), std::invalid_argument);
}

LatheSetup quietSetup() {
    LatheSetup s;
    s.warmUp.diameterShiftMm = 0.0;
    s.wear.diameterGrowthMm = 0.0;
    s.beamElementMm = 5.0;
    return s;
}

TEST(LatheSimulator, FinishedDiameterIsTheSelfConsistentCut) {
    const LatheSetup setup = quietSetup();
    LatheSimulator sim(setup, {0.0, 162.5, 325.0}, LatheDisturbanceModel::none(3));
    const TurnedPart part = sim.machine(PartCorrection{1, {}, {}, {}});
    const double k = sim.nominalRadialForceN() / setup.cutting.depthOfCutMm;  // N/mm
    for (std::size_t i = 0; i < part.zMm.size(); ++i) {
        const double ck = sim.complianceMmPerN()[i] * k;
        // r = r_nom + C K (R_blank - r)  =>  error on diameter = 2 C K a / (1 + C K)
        const double expected = 2.0 * ck * setup.cutting.depthOfCutMm / (1.0 + ck);
        EXPECT_NEAR(part.diameterMm[i] - setup.workpiece.finishDiameterMm, expected, 1e-12);
    }
    // The error is a barrel: larger in the middle than at either end.
    const auto mid = part.zMm.size() / 2;
    EXPECT_GT(part.diameterMm[mid], part.diameterMm.front());
    EXPECT_GT(part.diameterMm[mid], part.diameterMm.back());
}

TEST(LatheSimulator, ACorrectionMovesTheDiameterByTheElasticGain) {
    const LatheSetup setup = quietSetup();
    LatheSimulator sim(setup, {0.0, 162.5, 325.0}, LatheDisturbanceModel::none(3));
    const TurnedPart plain = sim.machine(PartCorrection{1, {}, {}, {}});
    PartCorrection c{1, {}, {}, {}};
    c.path.zMm = {0.0, 325.0};
    c.path.xCorrectionMm = {-0.05, -0.05};  // towards the axis
    const TurnedPart corrected = sim.machine(c);
    for (std::size_t i = 0; i < plain.zMm.size(); ++i) {
        const double gain = sim.correctionGainAt(i);
        EXPECT_LT(gain, 2.0);
        EXPECT_GT(gain, 1.5);
        EXPECT_NEAR(corrected.diameterMm[i] - plain.diameterMm[i], -0.05 * gain, 1e-12);
    }
}

TEST(LatheSimulator, WarmUpAndToolWearFollowThePapersNumbers) {
    LatheSetup setup;  // paper 000: 0.004 mm over 10 parts; 0.004 mm over a 5-part tool life
    setup.beamElementMm = 5.0;
    LatheSimulator sim(setup, {162.5}, LatheDisturbanceModel::none(1));
    EXPECT_NEAR(sim.warmUpShiftMm(1), -0.0002, 1e-15);
    EXPECT_NEAR(sim.warmUpShiftMm(10), -0.0038, 1e-15);
    EXPECT_NEAR(sim.warmUpShiftMm(11), -0.004, 1e-15);
    EXPECT_NEAR(sim.warmUpShiftMm(500), -0.004, 1e-15);
    EXPECT_NEAR(sim.toolWearMm(1), 0.0, 1e-15);
    EXPECT_NEAR(sim.toolWearMm(5), 0.0032, 1e-15);
    EXPECT_NEAR(sim.toolWearMm(6), 0.0, 1e-15) << "a new edge after 5 parts";
    EXPECT_NEAR(sim.toolWearMm(8), 0.0016, 1e-15);
    EXPECT_EQ(sim.toolChangeOffsetMm(3), 0.0);
    setup.wear.changeRepeatabilityMm = 0.002;
    LatheSimulator withChanges(setup, {162.5}, LatheDisturbanceModel::none(1));
    EXPECT_EQ(withChanges.toolChangeOffsetMm(1), withChanges.toolChangeOffsetMm(5)) << "same edge";
    EXPECT_NE(withChanges.toolChangeOffsetMm(5), withChanges.toolChangeOffsetMm(6)) << "new edge";
}

TEST(LatheSimulator, RefusesABadSetUp) {
    LatheSetup setup;
    setup.cutting.depthOfCutMm = 20.0;
    EXPECT_THROW(LatheSimulator(setup, {162.5}, LatheDisturbanceModel::none(1)), std::invalid_argument);
    setup = LatheSetup{};
    EXPECT_THROW(LatheSimulator(setup, {162.5, 100.0}, LatheDisturbanceModel::none(2)), std::invalid_argument);
    EXPECT_THROW(LatheSimulator(setup, {400.0}, LatheDisturbanceModel::none(1)), std::invalid_argument);
    EXPECT_THROW(LatheSimulator(setup, {0.0, 325.0}, LatheDisturbanceModel::none(3)), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
