// Paper 002's results on the 1v340-feed-drives scenario (the engine defaults are that preset's values):
// on held-out moves of another seed the network's pulse cuts the mean trajectory error by at least 60 %
// (paper, Fig. 3: 0.04673 -> 0.01453 mm, -69 %); when the Z friction rises by 30 % mid-run the error
// rises above the controller's prediction, retraining triggers within the monitor's window and the
// reduction after it is at least 50 % (issue 15).
#include <gtest/gtest.h>

#include "core/sim/feed_drives/corner_work_run.h"

namespace tt::core {
namespace {

class CornerPaperResult : public ::testing::Test {
protected:
    // One training for the suite: 200 moves of seed 1 (about 2 s).
    static void SetUpTestSuite() { s_training = new CornerNetTraining(trainCornerNet(CornerScenario{}, 200, 1)); }
    static void TearDownTestSuite() {
        delete s_training;
        s_training = nullptr;
    }
    static CornerNetTraining* s_training;
};

CornerNetTraining* CornerPaperResult::s_training = nullptr;

TEST_F(CornerPaperResult, BestPulsesOfTheTrainingMovesCutTheErrorByMoreThanTheNetworkMust) {
    const AxisPulseSummary x = summarisePulses(FeedAxis::X, s_training->examples);
    EXPECT_GT(x.reductionPct, 65.0);   // the optimum per move: 72.7 % (README)
    EXPECT_GT(x.meanWithoutMm, 0.02);  // the paper's scale: 0.047 mm in its experiment
    EXPECT_LT(x.meanWithoutMm, 0.08);
    EXPECT_LT(x.meanAbsAmplitudeV, 0.5);
}

TEST_F(CornerPaperResult, HeldOutMovesOfAnotherSeedLoseAtLeastSixtyPercentOfTheirError) {
    const CornerScenario scenario;
    CorrectiveNet net = s_training->net;
    const std::vector<CornerMove> moves = drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, 100, 2);
    const CornerWorkResult r = runCornerWork(scenario, net, toNetSamples(s_training->examples), moves, {});
    EXPECT_GE(r.reductionPct, 60.0) << r.meanWithoutMm << " -> " << r.meanWithMm;  // paper: 69 %
    EXPECT_TRUE(r.retrains.empty());  // nothing drifted: the monitor stays quiet
    int hit = 0;
    for (const CornerWorkMove& m : r.moves)
        hit += m.hitByLoad ? 1 : 0;
    EXPECT_GT(hit, 0);  // misses were there and were ignored
}

TEST_F(CornerPaperResult, ThirtyPercentMoreZFrictionTriggersRetrainingThatKeepsHalfTheErrorOff) {
    CornerScenario scenario;
    const int window = scenario.retraining.monitor.windowCorners;
    CorrectiveNet net = s_training->net;
    const std::vector<CornerMove> moves = drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, 80, 3);
    CornerDrift drift;
    drift.factor = 1.3;
    const CornerWorkResult r = runCornerWork(scenario, net, toNetSamples(s_training->examples), moves, drift);
    ASSERT_EQ(r.driftAtMove, 40);
    ASSERT_FALSE(r.retrains.empty());
    const int first = r.retrains.front().move;
    EXPECT_GE(first, r.driftAtMove);           // no retraining before the drift
    EXPECT_LT(first, r.driftAtMove + window);  // and within the window after it
    // The error rose above what the controller's model predicted: that is what triggered it.
    EXPECT_GT(r.checks[static_cast<std::size_t>(first)].differenceFraction,
              scenario.retraining.monitor.thresholdFraction);
    for (int i = window; i < r.driftAtMove; ++i)
        EXPECT_LT(std::abs(r.checks[static_cast<std::size_t>(i)].differenceFraction),
                  scenario.retraining.monitor.thresholdFraction);
    // The friction found is the drift: Z up by about 30 % (per-corner scatter 5 %), X unchanged.
    EXPECT_NEAR(r.retrains.front().friction.zFactor, 1.3, 0.15);
    EXPECT_NEAR(r.retrains.front().friction.xFactor, 1.0, 0.1);
    ASSERT_TRUE(r.reductionAfterRetrainPct.has_value());
    EXPECT_GE(*r.reductionAfterRetrainPct, 50.0);
    EXPECT_EQ(net.record().retrainings, static_cast<int>(r.retrains.size()));
    // The same moves with the monitor only watching: the retrained network does no worse than the old
    // one after the retraining (on this machine the two are within a few tenths of a per cent, README).
    CorrectiveNet old = s_training->net;
    const CornerWorkResult watched =
        runCornerWork(scenario, old, toNetSamples(s_training->examples), moves, drift, /*retrain=*/false);
    EXPECT_TRUE(watched.retrains.empty());
    double without = 0.0, retrained = 0.0, kept = 0.0;
    for (std::size_t i = static_cast<std::size_t>(first) + 1; i < moves.size(); ++i) {
        without += watched.moves[i].without.meanErrorMm;
        kept += watched.moves[i].with.meanErrorMm;
        retrained += r.moves[i].with.meanErrorMm;
    }
    EXPECT_NEAR(100.0 * (1.0 - retrained / without), *r.reductionAfterRetrainPct, 1e-9);
    EXPECT_LE(retrained, kept * 1.01);
}

}  // namespace
}  // namespace tt::core
