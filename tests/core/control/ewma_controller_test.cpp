#include "core/control/ewma_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tt::core {
namespace {

EwmaController oneAxis(double weight, const CorrectionLimits& limits = {}, double deadBand = 0.0,
                       double warning = std::numeric_limits<double>::infinity(),
                       double alarm = std::numeric_limits<double>::infinity()) {
    EwmaOptions o;
    o.weight = weight;
    o.deadBandMm = deadBand;
    o.warningMm = warning;
    o.alarmMm = alarm;
    return EwmaController(Eigen::VectorXd::Constant(1, 2.0), limits, o);
}

PartMeasurement at(std::int64_t part, double value) {
    return {part, Eigen::VectorXd::Constant(1, value)};
}

// Hand computation with k_i = 2, lambda = 0.5: offset(k) = 0.5 (m - 2 u(k)) + 0.5 offset(k-1), u = -offset/2.
TEST(EwmaController, FollowsTheRecursionByHand) {
    EwmaController c = oneAxis(0.5);
    EXPECT_DOUBLE_EQ(c.nextCorrection(1)(0), 0.0);
    c.addMeasurement(at(1, 0.1));  // uncorrected 0.1 -> offset 0.05
    EXPECT_DOUBLE_EQ(c.nextCorrection(2)(0), -0.025);
    c.addMeasurement(at(2, 0.04));  // uncorrected 0.04 + 0.05 = 0.09 -> offset 0.07
    EXPECT_DOUBLE_EQ(c.offsetMm()(0), 0.07);
    EXPECT_DOUBLE_EQ(c.nextCorrection(3)(0), -0.035);
}

TEST(EwmaController, LateMeasurementIsPairedWithItsOwnPartsCorrection) {
    EwmaController c = oneAxis(1.0);
    c.nextCorrection(1);
    c.nextCorrection(2);
    c.addMeasurement(at(1, 0.1));  // u(1) = 0 -> offset 0.1
    EXPECT_DOUBLE_EQ(c.nextCorrection(3)(0), -0.05);
    c.nextCorrection(4);
    c.addMeasurement(at(3, 0.0));  // u(3) = -0.05: uncorrected 0.1, not 0.0 - 2 u(4)
    EXPECT_DOUBLE_EQ(c.offsetMm()(0), 0.1);
}

TEST(EwmaController, DeadBandHoldsTheCorrection) {
    EwmaController c = oneAxis(1.0, {}, 0.02);
    c.nextCorrection(1);
    c.addMeasurement(at(1, 0.015));  // inside the dead band: no correction
    EXPECT_DOUBLE_EQ(c.nextCorrection(2)(0), 0.0);
    c.addMeasurement(at(2, 0.03));  // outside: correct
    EXPECT_DOUBLE_EQ(c.nextCorrection(3)(0), -0.015);
}

TEST(EwmaController, WarningAndAlarmBands) {
    EwmaController c = oneAxis(1.0, {}, 0.0, 0.05, 0.1);
    c.nextCorrection(1);
    c.nextCorrection(2);
    c.nextCorrection(3);
    EXPECT_TRUE(c.addMeasurement(at(1, 0.02)).allAccepted());
    EXPECT_EQ(c.bands()[0], ToleranceBand::Ok);
    EXPECT_TRUE(c.addMeasurement(at(2, 0.06)).allAccepted());
    EXPECT_EQ(c.bands()[0], ToleranceBand::Warning);
    const MeasurementVerdict v = c.addMeasurement(at(3, -0.12));
    EXPECT_FALSE(v.accepted[0]);
    EXPECT_NE(describe(v.reasons[0]).find("alarm"), std::string::npos) << describe(v.reasons[0]);
    EXPECT_EQ(c.bands()[0], ToleranceBand::Alarm);
    EXPECT_DOUBLE_EQ(c.offsetMm()(0), 0.06) << "the alarmed value is not used";
}

TEST(EwmaController, LimitsCauseNoWindUp) {
    // Constant 0.1 mm offset, corrections limited to 0.01 mm: the offset estimate still converges to
    // 0.1 because each measurement is paired with the applied (clamped) correction.
    EwmaController c = oneAxis(0.3, {0.01, 0.005});
    Eigen::VectorXd u = Eigen::VectorXd::Zero(1);
    for (int p = 1; p <= 100; ++p) {
        const Eigen::VectorXd next = c.nextCorrection(p);
        EXPECT_LE(std::abs(next(0)), 0.01 + 1e-15);
        EXPECT_LE(std::abs(next(0) - u(0)), 0.005 + 1e-15);
        u = next;
        c.addMeasurement(at(p, 0.1 + 2.0 * u(0)));
    }
    EXPECT_NEAR(c.offsetMm()(0), 0.1, 1e-12);
    EXPECT_DOUBLE_EQ(u(0), -0.01);
}

TEST(EwmaController, RejectsBadInputAndOptions) {
    EwmaController c = oneAxis(0.5);
    EXPECT_NE(describe(c.addMeasurement(at(1, 0.0)).reasons[0]).find("not been machined"), std::string::npos);
    c.nextCorrection(1);
    EXPECT_EQ(describe(c.addMeasurement(at(1, std::nan(""))).reasons[0]), "not measured");
    EXPECT_EQ(describe(c.addMeasurement(at(1, INFINITY)).reasons[0]), "not a finite number");
    EXPECT_TRUE(c.addMeasurement(at(1, 0.01)).allAccepted());
    EXPECT_NE(describe(c.addMeasurement(at(1, 0.01)).reasons[0]).find("already measured"), std::string::npos);
    EXPECT_THROW(c.nextCorrection(3), std::invalid_argument);
    EXPECT_THROW(oneAxis(0.0), std::invalid_argument);
    EXPECT_THROW(oneAxis(1.5), std::invalid_argument);
    EXPECT_THROW(oneAxis(0.5, {}, -0.1), std::invalid_argument);
    EXPECT_THROW(oneAxis(0.5, {}, 0.0, 0.2, 0.1), std::invalid_argument);
    EXPECT_THROW(oneAxis(0.5, {0.0, 1.0}), std::invalid_argument);
}

TEST(EwmaController, SaveAndRestoreRoundTripExactly) {
    EwmaOptions o;
    o.weight = 0.35;
    o.deadBandMm = 0.001;
    o.warningMm = 0.05;
    o.alarmMm = 0.2;
    EwmaController a(Eigen::Vector3d(2, 2, 1.5), {0.2, 0.05}, o);
    for (int p = 1; p <= 40; ++p) {
        a.nextCorrection(p);
        if (p > 2) a.addMeasurement({p - 2, Eigen::Vector3d(0.01 * std::sin(p), 0.03, -0.02 * std::cos(p))});
    }
    EwmaController b(Eigen::Vector3d(2, 2, 1.5), {0.2, 0.05}, o);
    b.restoreState(a.saveState());
    EXPECT_EQ(b.saveState().values, a.saveState().values);
    for (int p = 41; p <= 60; ++p) {
        const Eigen::Vector3d m(0.02 * std::cos(p), -0.01, 0.015);
        EXPECT_EQ(a.nextCorrection(p), b.nextCorrection(p));
        a.addMeasurement({p - 2, m});
        b.addMeasurement({p - 2, m});
    }
    EwmaOptions other = o;
    other.weight = 0.4;
    EwmaController c(Eigen::Vector3d(2, 2, 1.5), {0.2, 0.05}, other);
    EXPECT_THROW(c.restoreState(a.saveState()), std::invalid_argument);
}

TEST(OpenLoopController, NeverCorrects) {
    OpenLoopController c(2);
    EXPECT_TRUE(c.nextCorrection(7).isZero(0.0));
    EXPECT_TRUE(c.addMeasurement({7, Eigen::Vector2d(0.3, 0.1)}).allAccepted());
    EXPECT_EQ(describe(c.addMeasurement({8, Eigen::Vector2d(0.3, 0.1)}).reasons[0]),
              "part 8 has not been machined yet");
    EXPECT_EQ(describe(c.addMeasurement({7, Eigen::Vector2d(std::nan(""), 0.1)}).reasons[0]), "not measured");
    EXPECT_THROW(c.nextCorrection(9), std::invalid_argument);
    OpenLoopController d(2);
    d.restoreState(c.saveState());
    EXPECT_EQ(d.saveState().values, c.saveState().values);
}

}  // namespace
}  // namespace tt::core
