// Every drift `trueturn corner` accepts runs with retraining (issue 25): each kind at both ends of its
// range 0.5 .. 3, on the carriage and, for the gain, on the cross slide too. A reduced grid on a lighter
// scenario (40 training moves, 30 work moves with the drift from move 10, a monitor window of 6 corners,
// one identification sweep, 10 validation moves) so it runs in seconds; the full grid on the preset
// (80 moves, drifts 0.5 .. 3, seeds 3 and 7) is in README with its command (scripts/corner-drift-grid.py).
// Before, a large friction drift stopped the run: each identification multiplied the model's friction
// again, until the model's carriage could not break away and its simulation never passed the interval.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sim/feed_drives/corner_work_run.h"

namespace tt::core {
namespace {

CornerScenario lightScenario() {
    CornerScenario s;
    s.training.moves = 40;
    s.training.network.maxEpochs = 3000;
    s.training.network.patience = 500;
    s.retraining.monitor.windowCorners = 6;
    s.retraining.validationMoves = 10;
    s.retraining.identification.sweeps = 1;
    return s;
}

TEST(CornerDriftGrid, EveryKindAtBothEndsOfTheRangeRunsWithRetraining) {
    const CornerScenario s = lightScenario();
    const CornerNetTraining trained = trainCornerNet(s, s.training.moves, 1);
    const std::vector<CornerMove> moves = drawCornerMoves(s.xSpeeds, s.zSpeeds, 30, 7);
    struct Case {
        DriveDriftKind kind;
        FeedAxis axis;
    };
    const Case cases[] = {{DriveDriftKind::Friction, FeedAxis::Z},
                          {DriveDriftKind::Gain, FeedAxis::Z},
                          {DriveDriftKind::Inertia, FeedAxis::Z},
                          {DriveDriftKind::Gain, FeedAxis::X}};
    int retrainings = 0;
    for (const Case& c : cases)
        for (double factor : {kMinDriveDriftFactor, kMaxDriveDriftFactor}) {
            SCOPED_TRACE(std::string(toString(c.kind)) + " " + toString(c.axis) + " x" + std::to_string(factor));
            CorrectiveNet net = trained.net;
            CornerDrift drift;
            drift.kind = c.kind;
            drift.axis = c.axis;
            drift.factor = factor;
            drift.atMove = 10;
            CornerWorkResult r;
            ASSERT_NO_THROW(r = runCornerWork(s, net, toNetSamples(trained.examples), moves, drift));
            ASSERT_EQ(r.moves.size(), moves.size());
            for (const CornerWorkMove& m : r.moves) {
                EXPECT_TRUE(std::isfinite(m.with.meanErrorMm));
                EXPECT_TRUE(std::isfinite(m.predicted.cost));
            }
            for (const CornerRetrainEvent& e : r.retrains) {
                ++retrainings;
                EXPECT_FALSE(e.verdict.failure.find("failed") != std::string::npos) << e.reason;
                // The model stays one that can move: static friction below 90 % of the peak torque.
                for (FeedAxis axis : {FeedAxis::X, FeedAxis::Z}) {
                    const FeedDriveAxisConfig& d = axisConfig(s.drives, axis);
                    EXPECT_LE(axisFactors(e.identified.factors, axis).friction * d.staticFrictionNm,
                              0.9 * d.torqueConstantNmPerA * d.currentLimitA + 1e-9);
                }
            }
        }
    EXPECT_GE(retrainings, 8);  // the grid did retrain: at least once per run on average
}

}  // namespace
}  // namespace tt::core
