// Force from the cross-feed current with dither (paper 001, way 1, fig. 1): friction far above
// the cutting force, the constant-velocity windows, and every refusal.
#include "core/control/dither_force_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/sim/boring/dither_profile.h"

namespace tt::core {
namespace {

// A kinematic drive: the slide follows the command exactly; the motor force is
// F = m a + c v + F_c sign(v) + P (P pushes the tool towards the axis), current F / k_p + noise.
struct Drive {
    double massKg = 860.0;
    double coulombN = 900.0;
    double viscousNsPerMm = 50.0;
    double kpNPerA = 150.0;
    double noiseA = 0.0;
    double feedMmPerS = 0.0;  // a taper's continuous X motion on top of the dither
};

std::vector<DriveSample> drive(const DitherConfig& dither, const Drive& d, double forceN, double cycleS,
                               double durationS, unsigned seed = 1) {
    const DitherProfile profile(dither);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<DriveSample> out;
    for (double t = cycleS; t <= durationS; t += cycleS) {
        const DitherState s = profile.at(t);
        const double v = s.velocityMmPerS + d.feedMmPerS;
        const double friction = v > 0.0 ? d.coulombN : (v < 0.0 ? -d.coulombN : 0.0);
        const double force = d.massKg * s.accelerationMmPerS2 / 1000.0 + d.viscousNsPerMm * v + friction + forceN;
        out.push_back({t, force / d.kpNPerA + d.noiseA * normal(rng), v, s.positionMm + d.feedMmPerS * t});
    }
    return out;
}

DitherEstimatorConfig config() {
    DitherEstimatorConfig c;
    c.currentToForceNPerA = 150.0;
    c.stiffnessNPerMm = 2474.0;
    return c;
}

struct Outcome {
    std::vector<ForceEstimate> estimates;
    DitherUpdate last;
};

Outcome feed(DitherForceEstimator& estimator, const std::vector<DriveSample>& samples) {
    Outcome r;
    for (const DriveSample& s : samples) {
        r.last = estimator.update(s);
        if (r.last.newEstimate) r.estimates.push_back(*r.last.estimate);
    }
    return r;
}

const DitherConfig kDither{0.01, 0.5, 0.6};  // the heavy-boring preset: ±10 µm, 0.5 s, 60 % constant velocity

TEST(DitherEstimator, FindsTheCuttingForceUnderFrictionNineTimesLarger) {
    // F_c = 900 N against P = 100 N, no noise: friction and viscous friction cancel between the
    // directions; the inertia force (860 kg · 2 mm/s² = 1.7 N) enters only through a sample at the
    // edge of a window, so P comes back within 0.5 N.
    DitherEstimatorConfig onePair = config();
    onePair.strokesAveraged = 1;  // the paper's algorithm: one forward and one reverse stroke
    DitherForceEstimator estimator(onePair);
    const Outcome run = feed(estimator, drive(kDither, Drive{}, 100.0, 0.02, 20.0));
    ASSERT_GE(run.estimates.size(), 70u);  // a new pair every half period after the first
    for (const ForceEstimate& e : run.estimates) {
        EXPECT_NEAR(e.forceN, 100.0, 0.5);
        // The paper's currents: I_fwd = (F_c + c V + P) / k_p, I_rev = (F_c + c V − P) / k_p with V = 0.1 mm/s.
        EXPECT_NEAR(e.forwardCurrentA, (900.0 + 5.0 + 100.0) / 150.0, 0.01);
        EXPECT_NEAR(e.reverseCurrentA, (900.0 + 5.0 - 100.0) / 150.0, 0.01);
        EXPECT_NEAR(e.deflectionMm, -e.forceN / 2474.0, 1e-12);
        EXPECT_NEAR(e.correctionMm, e.forceN / 2474.0, 1e-12);
        // 0.15 s of constant velocity at a 20 ms PLC cycle, plus ramp samples within 15 % of V.
        EXPECT_GE(e.forwardSamples, 7);
        EXPECT_LE(e.forwardSamples, 9);
    }
}

TEST(DitherEstimator, AveragesCurrentNoiseToWithinAFewNewtons) {
    // Noise 0.3 A RMS per sample (45 N at k_p = 150 N/A) with friction 9 × the force.
    Drive d;
    d.noiseA = 0.3;
    DitherForceEstimator estimator(config());
    const Outcome run = feed(estimator, drive(kDither, d, 100.0, 0.02, 60.0, 11));
    ASSERT_GE(run.estimates.size(), 200u);
    double sum = 0.0;
    for (const ForceEstimate& e : run.estimates)
        sum += e.forceN;
    // One pair averages 7 + 7 samples: σ ≈ 150 · 0.3 / sqrt(7) / sqrt(2) ≈ 12 N; averaging the last
    // 4 strokes per direction halves that to about 6 N, so every estimate is within 4 σ = 24 N
    // and their mean within 3 N.
    for (const ForceEstimate& e : run.estimates) {
        EXPECT_NEAR(e.forceN, 100.0, 24.0);
        EXPECT_LE(e.strokesUsed, 8);
    }
    EXPECT_NEAR(sum / static_cast<double>(run.estimates.size()), 100.0, 3.0);
}

TEST(DitherEstimator, WorksAcrossThePlcCycleRange) {
    // 10 ms and 100 ms PLC cycles (paper 001: 10..100 ms); at 100 ms a 2 s period leaves 6 samples.
    for (const auto& [cycle, dither] : {std::pair{0.01, kDither}, std::pair{0.1, DitherConfig{0.02, 2.0, 0.6}}}) {
        DitherForceEstimator estimator(config());
        const Outcome run = feed(estimator, drive(dither, Drive{}, 250.0, cycle, 30.0));
        ASSERT_FALSE(run.estimates.empty()) << cycle << ": " << run.last.reason;
        EXPECT_NEAR(run.estimates.back().forceN, 250.0, 1.0) << cycle;
    }
}

TEST(DitherEstimator, RefusesATaperOrContourSegment) {
    DitherForceEstimator estimator(config());
    feed(estimator, drive(kDither, Drive{}, 100.0, 0.02, 5.0));
    ASSERT_TRUE(estimator.state().estimate);
    estimator.setSegment(SegmentKind::Taper);
    const DitherUpdate u = estimator.update({5.02, 6.0, 0.1, 0.0});
    EXPECT_FALSE(u.estimate);
    EXPECT_EQ(u.refusal, DitherRefusal::NotCylindrical);
    EXPECT_NE(u.reason.find("taper"), std::string::npos);
    estimator.setSegment(SegmentKind::Contour);
    EXPECT_NE(estimator.update({5.04, 6.0, 0.1, 0.0}).reason.find("contour"), std::string::npos);
}

TEST(DitherEstimator, DetectsATaperFromUnequalSpeeds) {
    // A taper moves X at 0.03 mm/s under the dither: 0.13 mm/s out, 0.07 mm/s in.
    Drive d;
    d.feedMmPerS = 0.03;
    DitherForceEstimator estimator(config());
    const Outcome run = feed(estimator, drive(kDither, d, 100.0, 0.02, 10.0));
    EXPECT_TRUE(run.estimates.empty());
    EXPECT_EQ(run.last.refusal, DitherRefusal::NotCylindrical);
    EXPECT_NE(run.last.reason.find("speeds differ"), std::string::npos) << run.last.reason;
}

TEST(DitherEstimator, RefusesAFeedMotionThatNeverReverses) {
    std::vector<DriveSample> feedOnly;
    for (double t = 0.02; t < 5.0; t += 0.02)
        feedOnly.push_back({t, 7.0, 0.2, 0.2 * t});
    DitherForceEstimator estimator(config());
    const Outcome run = feed(estimator, feedOnly);
    EXPECT_EQ(run.last.refusal, DitherRefusal::NotCylindrical);
    EXPECT_NE(run.last.reason.find("without reversing"), std::string::npos) << run.last.reason;
}

TEST(DitherEstimator, RefusesWhenTheSlideDoesNotMove) {
    // Stuck slide: velocity noise only, never above the 0.005 mm/s threshold.
    std::mt19937_64 rng(3);
    std::normal_distribution<double> normal(0.0, 0.0005);
    std::vector<DriveSample> stuck;
    for (double t = 0.02; t < 4.0; t += 0.02)
        stuck.push_back({t, 0.7, normal(rng), 0.0});
    DitherForceEstimator estimator(config());
    const Outcome run = feed(estimator, stuck);
    EXPECT_EQ(run.last.refusal, DitherRefusal::SlideNotMoving);
    EXPECT_NE(run.last.reason.find("has not moved for "), std::string::npos) << run.last.reason;
}

TEST(DitherEstimator, RefusesStrokesTooShortToTrust) {
    // ±5 µm dither, but at least 15 µm per stroke is asked for.
    DitherEstimatorConfig c = config();
    c.minStrokeMm = 0.015;
    DitherForceEstimator estimator(c);
    const Outcome run = feed(estimator, drive(DitherConfig{0.005, 0.5, 0.6}, Drive{}, 100.0, 0.02, 5.0));
    EXPECT_TRUE(run.estimates.empty());
    EXPECT_EQ(run.last.refusal, DitherRefusal::SlideNotMoving);
    EXPECT_NE(run.last.reason.find("moved only"), std::string::npos) << run.last.reason;
}

TEST(DitherEstimator, RefusesAVelocityWindowTooShortForThePlcCycle) {
    // 0.4 s period, 50 % at constant velocity: 0.1 s per stroke, one or two samples at 100 ms.
    DitherForceEstimator estimator(config());
    const Outcome run = feed(estimator, drive(DitherConfig{0.02, 0.4, 0.5}, Drive{}, 100.0, 0.1, 10.0));
    EXPECT_TRUE(run.estimates.empty());
    EXPECT_EQ(run.last.refusal, DitherRefusal::WindowTooShort);
    EXPECT_NE(run.last.reason.find("at constant velocity"), std::string::npos) << run.last.reason;
}

TEST(DitherEstimator, IgnoresACorruptSampleAndRecoversAfterARefusal) {
    DitherForceEstimator estimator(config());
    auto samples = drive(kDither, Drive{}, 100.0, 0.02, 10.0);
    samples[120].currentA = std::numeric_limits<double>::quiet_NaN();
    const Outcome run = feed(estimator, samples);
    ASSERT_FALSE(run.estimates.empty());
    EXPECT_NEAR(run.estimates.back().forceN, 100.0, 0.5);
    estimator.setSegment(SegmentKind::Taper);
    estimator.update({10.02, 6.0, 0.1, 0.0});
    estimator.setSegment(SegmentKind::Cylinder);
    EXPECT_EQ(estimator.state().refusal, DitherRefusal::WaitingForStrokes);
}

TEST(DitherEstimator, RejectsNonPhysicalConfiguration) {
    DitherEstimatorConfig c = config();
    c.currentToForceNPerA = 0.0;
    EXPECT_THROW(DitherForceEstimator{c}, std::invalid_argument);
    c = config();
    c.stiffnessNPerMm = -1.0;
    EXPECT_THROW(DitherForceEstimator{c}, std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
