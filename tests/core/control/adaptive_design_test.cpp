// The adaptive loop's designs (core/control/adaptive_design.h): the robust fallback, the re-synthesis with its
// margins checked, the lag wrapper and the controllers told what was really applied.
#include <gtest/gtest.h>

#include <cmath>

#include "core/control/adaptive_design.h"
#include "core/control/lagged_controller.h"
#include "tests/core/support/closed_loop_record.h"

namespace tt::core {
namespace {

// The fallback EWMA at z = 1 around a plant of gain r times the model's: offset(k) = (1 - lambda r) offset(k-1) +
// lambda d, stable for lambda r < 2; with one more part of delay the characteristic is q^2 - q + lambda r, stable
// for lambda r < 1. Covering r <= 2 with the extra part needs lambda < 0.5: the largest weight on the 0.01 grid is
// 0.49 (derived here; the design finds it with closed-loop eigenvalues).
TEST(FallbackDesign, AtDelayOneIsTheAnalyticWeight) {
    const FallbackDesign f = designFallback(1);
    EXPECT_NEAR(f.weight, 0.49, 1e-12);
    EXPECT_EQ(f.delayParts, 1);
    ASSERT_TRUE(f.margins.gain);
    EXPECT_NEAR(*f.margins.gain, 2.0 / 0.49, 1e-3);  // the upper gain margin at delay 1: lambda r = 2
    EXPECT_GE(f.margins.extraPartsTolerated, 1);
}

// For every delay the fallback's loop is stable for plant gains 0.5 .. 2 times the model's at the delay and one part
// more (checked again here on a finer grid than the design's) and not for a weight 0.01 larger.
TEST(FallbackDesign, CoversHalfToTwiceTheGainAndOneMorePart) {
    double previous = 1.0;
    for (int z = 1; z <= kMaxDelay; ++z) {
        const FallbackDesign f = designFallback(z);
        for (int extra = 0; extra <= 1; ++extra) {
            const LoopController c = ewmaLoopController(Eigen::VectorXd::Ones(1), z, f.weight);
            for (double r = 0.5; r <= 2.0 + 1e-9; r += 0.01)
                EXPECT_TRUE(closedLoopStable(Eigen::VectorXd::Constant(1, r), z + extra, c))
                    << "z = " << z << " + " << extra << ", gain x " << r;
        }
        const LoopController larger = ewmaLoopController(Eigen::VectorXd::Ones(1), z, f.weight + 0.01);
        EXPECT_FALSE(closedLoopStable(Eigen::VectorXd::Constant(1, 2.0), z + 1, larger)) << "z = " << z;
        EXPECT_LT(f.weight, previous + 1e-12) << "a longer delay needs a smaller weight";
        previous = f.weight;
    }
    EXPECT_THROW(designFallback(0), std::invalid_argument);
}

// The fallback controller is the setup's EWMA with that weight on the model's gains (and the model's lag).
TEST(FallbackDesign, ControllerIsTheSetupsEwma) {
    RunToRunSetup s = test::paper2012Setup(2);
    const auto c = makeFallbackController(s, designFallback(2));
    EXPECT_EQ(c->name(), "ewma");
    EXPECT_EQ(c->pointCount(), 5);
}

// The re-synthesis for an identification of the model itself passes its margins at z = 2 with the setup's weights
// (the preset's LQG has gain margins about 1.9 there); the required gain range is at least 25 % either way.
TEST(AdaptedDesign, OfTheTrueModelPasses) {
    const auto controller = test::paperLqg(2);
    const LoopHistory h = test::runClosedLoop(*controller, 2, 1.0, 0, 2002, 5);
    const PlantIdentification id = identifyPlant(h, test::paperIdentification(2));
    const AdaptedDesign d = designAdapted(test::paper2012Setup(2), id, "test");
    EXPECT_TRUE(d.passes) << d.why;
    EXPECT_DOUBLE_EQ(d.r2Factor, 1.0);
    EXPECT_GE(d.requiredGainFactor, 1.0 + kMinGainUncertainty);
    ASSERT_TRUE(d.setup.model);
    EXPECT_EQ(d.setup.model->lagParts, 0);
    EXPECT_EQ(d.setup.model->source, "test");
    EXPECT_TRUE(d.margins.closedLoopStable);
    EXPECT_GE(d.worst.gain, d.requiredGainFactor);
}

// A design whose margins cannot cover the required gain change is refused with the margin named.
TEST(AdaptedDesign, RefusedWhenTheMarginsCannotCoverTheUncertainty) {
    const auto controller = test::paperLqg(2);
    const LoopHistory h = test::runClosedLoop(*controller, 2, 1.0, 0, 2002, 6);
    RunToRunSetup withModel = test::paper2012Setup(2);
    withModel.model = controllerModelFrom(identifyPlant(h, test::paperIdentification(2)), "test");
    const AdaptedDesign d = designForModel(withModel, 1e6);  // a gain a million times off: no LQG covers it
    EXPECT_FALSE(d.passes);
    EXPECT_NE(d.why.find("gain margin"), std::string::npos) << d.why;
    EXPECT_NE(d.why.find("also with R2 up to"), std::string::npos) << d.why;
}

// The ARMA form of paper-2012's filter (z + 0.246)/(z - 0.9215): AR 0.9215, MA 0.246, and the innovation variance
// that gives the stationary 0.0013 mm^2.
TEST(AdaptedDesign, ArmaFormOfThePresetFilter) {
    const std::optional<ArmaForm> a = armaForm(test::paper2012Disturbance());
    ASSERT_TRUE(a);
    ASSERT_EQ(a->ar.size(), 1u);
    ASSERT_EQ(a->ma.size(), 1u);
    EXPECT_NEAR(a->ar[0], 0.9215, 1e-12);
    EXPECT_NEAR(a->ma[0], 0.246, 1e-12);
    EXPECT_NEAR(a->noiseVarianceMm2, test::paperInnovationVariance(), 1e-12);
    EXPECT_FALSE(armaForm(DisturbanceModel({DisturbanceComponent::randomWalk(1e-6)})));
    const PlantModelRecord r = modelRecord(test::paper2012Setup(3));
    EXPECT_EQ(r.delayParts, 3);
    EXPECT_EQ(r.points.size(), 5u);
    EXPECT_TRUE(std::isnan(r.points[0].gainStdErr));
}

// A recorded identified model makes the same controller's model again (a resumed run).
TEST(AdaptedDesign, RecordRoundTrip) {
    const auto controller = test::paperLqg(1);
    const PlantIdentification id =
        identifyPlant(test::runClosedLoop(*controller, 1, 1.0, 1, 2002, 9), test::paperIdentification(1));
    const PlantModelRecord r = modelRecord(id, "parts 1 .. 2000");
    const ControllerModel back = controllerModelFrom(r, test::paper2012Setup(1));
    const ControllerModel direct = controllerModelFrom(id, "parts 1 .. 2000");
    EXPECT_EQ(back.lagParts, 1);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_DOUBLE_EQ(back.gain[i], direct.gain[i]);
        EXPECT_DOUBLE_EQ(back.disturbance[i].stationaryVarianceMm2(), direct.disturbance[i].stationaryVarianceMm2());
    }
    EXPECT_NEAR((back.innovationCorrelation - direct.innovationCorrelation).cwiseAbs().maxCoeff(), 0.0, 1e-15);
}

// The lag wrapper asks the inner controller for the part its correction acts on, passes the applied correction on
// at that number, and stamps the innovations with the lag and the correlation.
TEST(LaggedController, ShiftsThePartNumbers) {
    RunToRunSetup s = test::paper2012Setup(1);
    s.plant.delay = 2;  // the inner design: z + lag = 1 + 1
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    auto inner = makeRunToRunController(s, plant, ControllerKind::Lqg, 1.0);
    auto reference = makeRunToRunController(s, plant, ControllerKind::Lqg, 1.0);
    const Eigen::MatrixXd r = Eigen::MatrixXd::Identity(5, 5);
    LaggedController lagged(std::move(inner), 1, r);
    EXPECT_EQ(lagged.lagParts(), 1);
    EXPECT_EQ(lagged.name(), "lqg");
    for (std::int64_t p = 1; p <= 6; ++p) {
        const Eigen::VectorXd m = Eigen::VectorXd::Constant(5, 0.01 * static_cast<double>(p));
        if (p >= 2) {
            lagged.addMeasurement({p - 1, m});
            reference->addMeasurement({p - 1, m});
        }
        const Eigen::VectorXd a = lagged.nextCorrection(p);
        const Eigen::VectorXd b = reference->nextCorrection(p + 1);
        EXPECT_NEAR((a - b).cwiseAbs().maxCoeff(), 0.0, 1e-15) << "part " << p;
    }
    const std::optional<Innovation> inn = lagged.lastInnovation();
    ASSERT_TRUE(inn);
    EXPECT_EQ(inn->lagParts, 1);
    EXPECT_EQ(inn->correlation.rows(), 5);
    EXPECT_THROW(LaggedController(nullptr, 0, {}), std::invalid_argument);
    EXPECT_THROW(LaggedController(test::paperLqg(1), 0, Eigen::MatrixXd::Identity(2, 2)), std::invalid_argument);
}

// A correction really applied differently (a hold, a transfer, a dither) moves the LQG's prediction of the part it
// acts on by k_i times the difference: at z = 1 the next filter step is that part (x(k+1|k) = A x + B u).
TEST(CorrectionApplied, MovesTheLqgPredictionByTheGain) {
    const RunToRunSetup s = test::paper2012Setup(1);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    LqgController lqg(plant, designLqg(plant, s.weights), s.limits);
    lqg.nextCorrection(1);
    lqg.addMeasurement({1, Eigen::VectorXd::Constant(5, 0.02)});
    const Eigen::VectorXd u = lqg.nextCorrection(2);
    const Eigen::VectorXd before = lqg.predictedDeviationMm();
    Eigen::VectorXd applied = u;
    applied(2) += 0.01;
    lqg.correctionApplied(2, applied);
    const Eigen::VectorXd after = lqg.predictedDeviationMm();
    EXPECT_NEAR(after(2) - before(2), 2.0 * 0.01, 1e-12);
    EXPECT_NEAR(after(0) - before(0), 0.0, 1e-15);
    EXPECT_NEAR((lqg.lastCorrectionMm() - applied).cwiseAbs().maxCoeff(), 0.0, 1e-15);
    lqg.correctionApplied(1, u);  // not the last part: ignored
    EXPECT_NEAR((lqg.predictedDeviationMm() - after).cwiseAbs().maxCoeff(), 0.0, 1e-15);
}

// The EWMA pairs the part's measurement with the correction really applied: its offset (the uncorrected
// deviation) is m - k_i u_applied.
TEST(CorrectionApplied, PairsTheEwmaMeasurementWithTheAppliedCorrection) {
    EwmaOptions o;
    o.weight = 1.0;
    EwmaController ewma(Eigen::VectorXd::Constant(1, 2.0), CorrectionLimits{}, o);
    ewma.nextCorrection(1);
    ewma.correctionApplied(1, Eigen::VectorXd::Constant(1, 0.01));
    ewma.addMeasurement({1, Eigen::VectorXd::Constant(1, 0.05)});
    EXPECT_NEAR(ewma.offsetMm()(0), 0.05 - 2.0 * 0.01, 1e-15);
}

}  // namespace
}  // namespace tt::core
