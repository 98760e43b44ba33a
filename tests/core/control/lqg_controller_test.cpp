#include "core/control/lqg_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/sim/statistics/stochastic_plant.h"
#include "support/lqg_test_support.h"

namespace tt::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A recorded disturbance and gauge-noise sequence, so several controllers can run in their own
/// closed loops on the same realisation: measured(p) = d(p) + k u_own(p) + v(p).
struct Realisation {
    std::vector<Eigen::VectorXd> d, v;
    Realisation(const RunToRunPlant& plant, int parts, std::uint64_t seed) {
        StochasticPlant sim(plant, seed);
        d.push_back(Eigen::VectorXd::Zero(plant.pointCount()));  // index 0 unused: parts start at 1
        v.push_back(Eigen::VectorXd::Zero(plant.pointCount()));
        for (int p = 1; p <= parts; ++p) {
            const PartDraw& draw = sim.draw(p);
            d.push_back(draw.disturbanceMm);
            v.push_back(draw.gaugeNoiseMm);
        }
    }
};

/// One controller in its own closed loop: the corrections it gave, and the measurement of each part.
struct Loop {
    const RunToRunPlant& plant;
    const Realisation& real;
    LqgController controller;
    std::vector<Eigen::VectorXd> u{Eigen::VectorXd()};
    int lastPart = 0;

    Loop(const RunToRunPlant& p, const Realisation& r, const LqgDesign& d, const CorrectionLimits& limits = {})
        : plant(p), real(r), controller(p, d, limits) {}

    Eigen::VectorXd measured(int part) const {
        return real.d[static_cast<std::size_t>(part)] + plant.gain.cwiseProduct(u[static_cast<std::size_t>(part)]) +
               real.v[static_cast<std::size_t>(part)];
    }
    MeasurementVerdict offer(int part, const Eigen::VectorXd& value) {
        return controller.addMeasurement({part, value});
    }
    MeasurementVerdict offer(int part) { return offer(part, measured(part)); }
    /// Nominal timing: the measurement of part p - z arrives just before the correction of part p.
    void machine(bool deliver = true) {
        const int p = ++lastPart;
        if (deliver && p - plant.delay >= 1) offer(p - plant.delay);
        u.push_back(controller.nextCorrection(p));
    }
};

struct Fixture {
    RunToRunSetup setup;
    RunToRunPlant plant;
    LqgDesign design;
    Realisation real;
    explicit Fixture(int delay, int parts = 400)
        : setup(test::paper2012Setup(delay)),
          plant(buildRunToRunPlant(setup.plant)),
          design(designLqg(plant, setup.weights)),
          real(plant, parts, 42) {}
};

TEST(LqgController, OutliersNanAndInfAreRejectedWithAReasonAndLeaveTheStateUntouched) {
    Fixture f(2);
    Loop a(f.plant, f.real, f.design), b(f.plant, f.real, f.design);
    for (int i = 0; i < 150; ++i) {
        a.machine();
        b.machine();
    }
    const int part = a.lastPart + 1 - f.plant.delay;  // measurement due before the next correction
    Eigen::VectorXd bad = a.measured(part);
    const double sigma = a.controller.predictedSigmaMm()(1);
    bad(1) = a.controller.predictedDeviationMm()(1) + 8.0 * sigma;  // exactly 8 sigma off
    bad(2) = kNaN;
    bad(3) = std::numeric_limits<double>::infinity();
    const MeasurementVerdict v = a.offer(part, bad);
    EXPECT_TRUE(v.accepted[0]);
    EXPECT_FALSE(v.accepted[1]);
    EXPECT_NE(describe(v.reasons[1]).find("outlier: 8"), std::string::npos) << describe(v.reasons[1]);
    EXPECT_NE(describe(v.reasons[1]).find("gate 5 sigma"), std::string::npos) << describe(v.reasons[1]);
    EXPECT_EQ(describe(v.reasons[2]), "not measured");
    EXPECT_EQ(describe(v.reasons[3]), "not a finite number");
    EXPECT_TRUE(v.accepted[4]);
    EXPECT_FALSE(v.allAccepted());
    // The rejected points are still open: the real values are accepted afterwards; the accepted ones
    // are not taken twice.
    const MeasurementVerdict again = a.offer(part);
    EXPECT_FALSE(again.accepted[0]);
    EXPECT_NE(describe(again.reasons[0]).find("already measured"), std::string::npos);
    EXPECT_TRUE(again.accepted[1] && again.accepted[2] && again.accepted[3]);
    // b gets the same real values once; from here both must behave identically.
    b.offer(part);
    for (int i = 0; i < 50; ++i) {
        a.machine();
        b.machine();
        EXPECT_EQ(a.u.back(), b.u.back()) << "part " << a.lastPart;
    }
}

// "Missing measurement -> time update only": skipping a part must equal offering exactly the
// predicted value (zero innovation).
TEST(LqgController, MissingMeasurementIsATimeUpdateOnly) {
    Fixture f(3);
    Loop a(f.plant, f.real, f.design), b(f.plant, f.real, f.design);
    for (int i = 0; i < 100; ++i) {
        a.machine();
        b.machine();
    }
    for (int gap = 0; gap < 3; ++gap) {
        const int part = b.lastPart + 1 - f.plant.delay;
        Eigen::VectorXd partial = b.measured(part);
        partial(2) = b.controller.predictedDeviationMm()(2);  // b: point 3 "measured" exactly as predicted
        b.offer(part, gap == 1 ? partial : b.controller.predictedDeviationMm());
        Eigen::VectorXd aValue = a.measured(part);
        aValue(2) = kNaN;  // a: point 3 not gauged
        if (gap == 1) a.offer(part, aValue);
        a.machine(false);
        b.machine(false);
        EXPECT_LT((a.u.back() - b.u.back()).cwiseAbs().maxCoeff(), 1e-15);
    }
    for (int i = 0; i < 30; ++i) {
        a.machine();
        b.machine();
        EXPECT_LT((a.u.back() - b.u.back()).cwiseAbs().maxCoeff(), 1e-14);
    }
}

// A late measurement is placed at its part index: after it arrives, the controller's disturbance
// estimate equals that of a controller that had it on time (the corrections given in between differ,
// the estimate of the disturbance does not depend on them). A controller that never gets it differs.
TEST(LqgController, LateMeasurementIsPlacedAtItsPartIndex) {
    Fixture f(2);
    Loop onTime(f.plant, f.real, f.design), late(f.plant, f.real, f.design), never(f.plant, f.real, f.design);
    for (int i = 0; i < 120; ++i) {
        onTime.machine();
        late.machine();
        never.machine();
    }
    const int held = late.lastPart + 1 - f.plant.delay;
    onTime.machine();
    late.machine(false);
    never.machine(false);
    for (int i = 0; i < 3; ++i) {
        onTime.machine();
        late.machine();
        never.machine();
    }
    const MeasurementVerdict v = late.offer(held);
    EXPECT_TRUE(v.allAccepted());
    const Eigen::VectorXd a = onTime.controller.predictedUncorrectedDeviationMm();
    EXPECT_LT((late.controller.predictedUncorrectedDeviationMm() - a).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT((never.controller.predictedUncorrectedDeviationMm() - a).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(LqgController, EarlyMeasurementWaitsForItsStep) {
    Fixture f(3);
    Loop early(f.plant, f.real, f.design), nominal(f.plant, f.real, f.design);
    for (int i = 0; i < 80; ++i) {
        early.machine();
        nominal.machine();
    }
    // The last machined part is measured right away (2 parts early with z = 3).
    const MeasurementVerdict v = early.offer(early.lastPart);
    EXPECT_TRUE(v.allAccepted());
    for (int i = 0; i < 20; ++i) {
        const int due = early.lastPart + 1 - f.plant.delay;
        if (due != 80) early.offer(due);
        early.machine(false);
        nominal.machine();
        EXPECT_EQ(early.u.back(), nominal.u.back()) << "part " << early.lastPart;
    }
}

TEST(LqgController, RejectsPartsNotMachinedTooOldOrAlreadyMeasured) {
    Fixture f(1);
    Loop a(f.plant, f.real, f.design);
    EXPECT_EQ(describe(a.offer(1, Eigen::VectorXd::Zero(5)).reasons[0]), "part 1 has not been machined yet");
    for (int i = 0; i < 100; ++i)
        a.machine();
    EXPECT_NE(describe(a.offer(101, Eigen::VectorXd::Zero(5)).reasons[4]).find("has not been machined"),
              std::string::npos);
    EXPECT_NE(describe(a.offer(10).reasons[0]).find("too late: the controller keeps the last 64 parts"),
              std::string::npos);
    EXPECT_NE(describe(a.offer(a.lastPart - 2).reasons[0]).find("already measured"), std::string::npos);
    EXPECT_THROW(a.offer(50, Eigen::VectorXd::Zero(4)), std::invalid_argument);
    EXPECT_THROW(a.controller.nextCorrection(a.lastPart + 2), std::invalid_argument);
}

// The estimator is told what was really applied: its estimate of the disturbance is exactly that of an
// unlimited controller on the same disturbance, however hard the limits clip (no wind-up).
TEST(LqgController, LimitsAreRespectedAndCauseNoWindUp) {
    Fixture f(1);
    // A large constant offset of 0.2 mm on top of the recorded disturbance at every point.
    Realisation shifted = f.real;
    for (auto& d : shifted.d)
        d.array() += 0.2;
    const CorrectionLimits limits{0.02, 0.004};
    Loop limited(f.plant, shifted, f.design, limits), free(f.plant, shifted, f.design);
    bool clipped = false;
    Eigen::VectorXd previous = Eigen::VectorXd::Zero(5);
    for (int i = 0; i < 200; ++i) {
        limited.machine();
        free.machine();
        const Eigen::VectorXd& u = limited.u.back();
        EXPECT_LE(u.cwiseAbs().maxCoeff(), 0.02 + 1e-15);
        EXPECT_LE((u - previous).cwiseAbs().maxCoeff(), 0.004 + 1e-15);
        previous = u;
        clipped = clipped || limited.controller.lastLimited().any();
        EXPECT_LT(
            (limited.controller.predictedUncorrectedDeviationMm() - free.controller.predictedUncorrectedDeviationMm())
                .cwiseAbs()
                .maxCoeff(),
            1e-12)
            << "part " << i + 1;
    }
    EXPECT_TRUE(clipped);
    EXPECT_NEAR(limited.u.back()(0), -0.02, 1e-15) << "held at the limit against the 0.2 mm offset";
}

TEST(LqgController, GateWidensAfterMissingMeasurementsSoTheFilterCannotBeLockedOut) {
    Fixture f(1, 600);
    Loop a(f.plant, f.real, f.design);
    // Start-up: the first reading far from the (zero) prior is accepted: the gate uses the stationary
    // disturbance variance, not the steady-state innovation variance.
    a.machine();
    EXPECT_GT(a.controller.predictedSigmaMm()(0), 0.03);
    EXPECT_TRUE(a.offer(1, Eigen::VectorXd::Constant(5, 0.1)).allAccepted());
    for (int i = 0; i < 200; ++i)
        a.machine();
    const double steady = a.controller.predictedSigmaMm()(0);
    EXPECT_LT(steady, 0.015);
    for (int i = 0; i < 30; ++i)
        a.machine(false);  // the gauge is away for 30 parts
    const double widened = a.controller.predictedSigmaMm()(0);
    EXPECT_GT(widened, 2.5 * steady);
    const int part = a.lastPart + 1 - f.plant.delay;
    const Eigen::VectorXd off = a.controller.predictedDeviationMm().array() + 6.0 * steady;
    EXPECT_TRUE(a.offer(part, off).allAccepted()) << "6 steady-state sigma, but inside the widened gate";
    for (int i = 0; i < 60; ++i)
        a.machine();
    EXPECT_NEAR(a.controller.predictedSigmaMm()(0), steady, 1e-12) << "back to the steady state";
}

TEST(LqgController, SaveAndRestoreRoundTripExactly) {
    Fixture f(3);
    Loop a(f.plant, f.real, f.design);
    // Parts 2, 11, 20, ..., 65 are not measured on time.
    for (int i = 0; i < 70; ++i)
        a.machine(i % 9 != 4);
    const int early = a.lastPart;
    EXPECT_TRUE(a.offer(early).allAccepted());  // an early one, 2 parts ahead of its step
    EXPECT_TRUE(a.offer(65).allAccepted());     // a late one
    const ControllerState saved = a.controller.saveState();
    EXPECT_EQ(saved.kind, "lqg");
    LqgController b(f.plant, f.design, CorrectionLimits{});
    b.restoreState(saved);
    EXPECT_EQ(b.saveState().values, saved.values);
    Loop c(f.plant, f.real, f.design);
    c.controller = b;
    c.u = a.u;
    c.lastPart = a.lastPart;
    for (int i = 0; i < 50; ++i) {
        const int due = a.lastPart + 1 - f.plant.delay;
        if (due != early) {
            a.offer(due);
            c.offer(due);
        }
        a.machine(false);
        c.machine(false);
        EXPECT_EQ(a.u.back(), c.u.back()) << "part " << a.lastPart;
    }
    EXPECT_EQ(a.controller.saveState().values, c.controller.saveState().values);
}

TEST(LqgController, RestoreRefusesAForeignOrDamagedState) {
    Fixture f(2);
    Loop a(f.plant, f.real, f.design);
    for (int i = 0; i < 10; ++i)
        a.machine();
    ControllerState s = a.controller.saveState();
    LqgController other(f.plant, f.design, CorrectionLimits{0.1, 0.05});  // different limits
    EXPECT_THROW(other.restoreState(s), std::invalid_argument);
    LqgController same(f.plant, f.design, CorrectionLimits{});
    const std::vector<double> before = same.saveState().values;
    ControllerState wrongKind = s;
    wrongKind.kind = "ewma";
    EXPECT_THROW(same.restoreState(wrongKind), std::invalid_argument);
    ControllerState truncated = s;
    truncated.values.pop_back();
    EXPECT_THROW(same.restoreState(truncated), std::invalid_argument);
    ControllerState nan = s;
    nan.values[10] = kNaN;
    EXPECT_THROW(same.restoreState(nan), std::invalid_argument);
    EXPECT_EQ(same.saveState().values, before) << "a refused state leaves the controller as it was";
    same.restoreState(s);
    EXPECT_EQ(same.saveState().values, s.values);
}

}  // namespace
}  // namespace tt::core
