// Random sources of the lathe simulator: seeded, reproducible in any order, with the variances the
// disturbance model and the micrometer specify.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/disturbance_model.h"
#include "core/sim/shaft/lathe_disturbance.h"
#include "core/sim/shaft/lathe_micrometer.h"
#include "core/sim/shaft/lathe_simulator.h"

namespace tt::core {
namespace {

double variance(const std::vector<double>& v) {
    double mean = 0.0;
    for (double x : v)
        mean += x;
    mean /= static_cast<double>(v.size());
    double s = 0.0;
    for (double x : v)
        s += (x - mean) * (x - mean);
    return s / static_cast<double>(v.size() - 1);
}

TEST(LatheDisturbance, SampleVarianceMatchesTheModel) {
    // Two points: AR(1) pole 0.9 of variance 0.0012 plus white 0.0001 (total 0.0013 mm², the open-loop
    // variance of Table 2 of paper 000), and pure white 0.0004.
    const std::vector<DisturbanceModel> points = {
        DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.0012), DisturbanceComponent::white(0.0001)}),
        DisturbanceModel({DisturbanceComponent::white(0.0004)})};
    LatheDisturbance d(LatheDisturbanceModel::fromPointModels(points), 7);
    const Eigen::VectorXd stationary = d.stationaryVarianceMm2();
    EXPECT_NEAR(stationary(0), 0.0013, 1e-12);
    EXPECT_NEAR(stationary(1), 0.0004, 1e-12);
    std::vector<double> a, b;
    for (int k = 1; k <= 40000; ++k) {
        const Eigen::VectorXd f = d.diameterMm(k);
        a.push_back(f(0));
        b.push_back(f(1));
    }
    // Standard error of a variance estimate from 40000 AR(1) samples at pole 0.9: about
    // sqrt(2 (1+0.81)/(1-0.81) / 40000) = 2.2 %; allow 3 sigma.
    EXPECT_NEAR(variance(a) / 0.0013, 1.0, 0.07);
    EXPECT_NEAR(variance(b) / 0.0004, 1.0, 0.03);
}

TEST(LatheDisturbance, ACommonShareCorrelatesThePointsAndKeepsEachPointsProcess) {
    const std::vector<DisturbanceModel> points(3, DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.0013)}));
    LatheDisturbance d(LatheDisturbanceModel::fromPointModels(points, 0.8).scaled(0.5), 3);
    // Each point: still AR(1) 0.9 with variance 0.0013, scaled by 0.5 in standard deviation.
    EXPECT_NEAR(d.stationaryVarianceMm2()(1), 0.25 * 0.0013, 1e-12);
    std::vector<double> a, b, lagged;
    for (int k = 1; k <= 40000; ++k) {
        const Eigen::VectorXd f = d.diameterMm(k);
        a.push_back(f(0));
        b.push_back(f(2));
    }
    double sab = 0.0, saa = 0.0, sbb = 0.0, lag = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        sab += a[k] * b[k];
        saa += a[k] * a[k];
        sbb += b[k] * b[k];
        if (k > 0) lag += a[k] * a[k - 1];
    }
    EXPECT_NEAR(sab / std::sqrt(saa * sbb), 0.8, 0.03) << "correlation between points = the common share";
    EXPECT_NEAR(lag / saa, 0.9, 0.02) << "the lag-1 autocorrelation of AR(1) 0.9 is kept";
    EXPECT_NEAR(variance(a) / (0.25 * 0.0013), 1.0, 0.07);
    EXPECT_THROW(LatheDisturbanceModel::fromPointModels(points, 1.5), std::invalid_argument);
    const std::vector<DisturbanceModel> mixed = {
        DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.001)}),
        DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.001), DisturbanceComponent::white(0.001)})};
    EXPECT_THROW(LatheDisturbanceModel::fromPointModels(mixed, 0.5), std::invalid_argument);
}

TEST(LatheDisturbance, SameSeedSameSequenceInAnyOrder) {
    const std::vector<DisturbanceModel> points = {DisturbanceModel({DisturbanceComponent::ar1(0.95, 0.001)})};
    LatheDisturbance forward(LatheDisturbanceModel::fromPointModels(points), 42);
    LatheDisturbance jumping(LatheDisturbanceModel::fromPointModels(points), 42);
    LatheDisturbance other(LatheDisturbanceModel::fromPointModels(points), 43);
    std::vector<double> seq;
    for (int k = 1; k <= 2000; ++k)
        seq.push_back(forward.diameterMm(k)(0));
    EXPECT_EQ(jumping.diameterMm(1500)(0), seq[1499]);
    EXPECT_EQ(jumping.diameterMm(3)(0), seq[2]) << "going back re-creates the sequence";
    EXPECT_EQ(jumping.diameterMm(2000)(0), seq[1999]);
    EXPECT_NE(other.diameterMm(10)(0), seq[9]);
}

TEST(LatheDisturbance, RandomWalkStartsAtZeroAndHasNoStationaryVariance) {
    const std::vector<DisturbanceModel> points = {DisturbanceModel({DisturbanceComponent::randomWalk(1e-6)})};
    LatheDisturbance d(LatheDisturbanceModel::fromPointModels(points), 1);
    EXPECT_THROW(d.stationaryVarianceMm2(), std::logic_error);
    EXPECT_LT(std::abs(d.diameterMm(1)(0)), 0.01);
}

TEST(LatheDisturbance, RefusesInconsistentMatrices) {
    LatheDisturbanceModel m = LatheDisturbanceModel::none(2);
    m.C = Eigen::MatrixXd::Zero(3, 0);
    EXPECT_THROW(LatheDisturbance(m, 1), std::invalid_argument);
    LatheDisturbanceModel w = LatheDisturbanceModel::none(1).withWhiteNoise({1e-6});
    w.W(0, 0) = -1.0;
    EXPECT_THROW(LatheDisturbance(w, 1), std::invalid_argument);
}

TEST(LatheMicrometerModel, ReadsToTheMicronWithThePapersError) {
    // Paper 000: 0.001 mm resolution, 0.001 mm at 95 % -> sigma = 0.001 / 1.96 = 0.00051 mm.
    const LatheMicrometerModel micrometer(LatheMicrometer{}, 5);
    std::vector<double> readings;
    for (int k = 1; k <= 20000; ++k) {
        const double r = micrometer.readMm(27.0, k, 0);
        EXPECT_NEAR(std::round(r * 1000.0), r * 1000.0, 1e-6) << "a whole number of microns";
        readings.push_back(r);
    }
    // Rounding to 0.001 adds 0.001²/12 to the variance (Sheppard's correction).
    const double expected = std::pow(0.001 / 1.96, 2) + 1e-6 / 12.0;
    EXPECT_NEAR(variance(readings) / expected, 1.0, 0.05);
    EXPECT_EQ(micrometer.readMm(27.0, 17, 2), micrometer.readMm(27.0, 17, 2)) << "reproducible";
    EXPECT_THROW(LatheMicrometerModel(LatheMicrometer{0.001, -1.0}, 1), std::invalid_argument);
}

TEST(LatheSimulator, APartDependsOnlyOnItsNumberAndCorrection) {
    LatheSetup setup;
    setup.beamElementMm = 2.5;  // 162.5 mm is a node
    setup.wear.changeRepeatabilityMm = 0.002;
    setup.seed = 99;
    const std::vector<DisturbanceModel> points(5, DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.0013)}));
    const std::vector<double> z = {0.0, 27.5, 162.5, 262.5, 325.0};
    LatheSimulator a(setup, z, LatheDisturbanceModel::fromPointModels(points));
    LatheSimulator b(setup, z, LatheDisturbanceModel::fromPointModels(points));
    const TurnedPart a50 = a.machine(PartCorrection{50, {}, {}, {}});
    b.machine(PartCorrection{10, {}, {}, {}});
    const TurnedPart b50 = b.machine(PartCorrection{50, {}, {}, {}});
    EXPECT_EQ(a50.diameterMm, b50.diameterMm);
    // Between the control points the random part follows the points (PCHIP), so at a point the
    // disturbance is exactly the model's.
    const std::vector<double> deterministic = a.deterministicErrorMm(50);
    LatheDisturbance reference(LatheDisturbanceModel::fromPointModels(points), 99);
    const Eigen::VectorXd f = reference.diameterMm(50);
    const double atMiddle = a50.diameterAtMm(162.5) - setup.workpiece.finishDiameterMm;
    const std::size_t mid = 65;
    EXPECT_NEAR(a50.zMm[mid], 162.5, 1e-9);
    EXPECT_NEAR(atMiddle, deterministic[mid] + f(2), 1e-12);
}

}  // namespace
}  // namespace tt::core
