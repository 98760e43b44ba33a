// Paper 002's results on the 1v340-feed-drives scenario (the engine defaults are that preset's values):
// on held-out moves of another seed the network's pulse cuts the mean trajectory error by at least 60 %
// (paper, Fig. 3: 0.04673 -> 0.01453 mm, -69 %). Retraining on drift (paper: "the parameters of the
// drive systems change with time"): a drift of the drive's velocity gain by 1.5x moves the best pulse,
// and the retrained network does at least 5 points better than the network kept; a friction or inertia
// drift hardly moves it here (the PI velocity loop rejects friction, and follows a 50 ms pulse whatever the
// inertia), so there the guard keeps the retraining from doing worse. After every drift the controller's
// prediction returns within the monitor's threshold. Where the velocity loop is as slow as the pulse (the
// 1v340-soft-drives preset) the inertia moves the best pulse too (CornerDriftPhysics below; the retraining's
// figure on that preset: tests/app/corner/corner_soft_drives_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

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

    /// The same moves with retraining and with the network kept (the monitor only watching).
    struct Compared {
        CornerWorkResult retrained;
        CornerWorkResult kept;
        int first = -1;             ///< the move after which the first retraining happened
        double retrainedPct = 0.0;  ///< reduction over the moves after it, retrained network
        double keptPct = 0.0;       ///< the same moves, network kept
        int acceptedRetrainings = 0;
    };
    static Compared compare(const CornerDrift& drift, unsigned long long seed, int count = 80) {
        const CornerScenario scenario;
        const std::vector<CornerMove> moves = drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, count, seed);
        const std::vector<NetSample> set = toNetSamples(s_training->examples);
        Compared c;
        CorrectiveNet net = s_training->net;
        c.retrained = runCornerWork(scenario, net, set, moves, drift);
        CorrectiveNet old = s_training->net;
        c.kept = runCornerWork(scenario, old, set, moves, drift, /*retrain=*/false);
        EXPECT_TRUE(c.kept.retrains.empty());
        for (const CornerRetrainEvent& e : c.retrained.retrains)
            c.acceptedRetrainings += e.verdict.accepted ? 1 : 0;
        EXPECT_EQ(net.record().retrainings, c.acceptedRetrainings);  // a refused network never replaced it
        if (c.retrained.retrains.empty()) return c;
        c.first = c.retrained.retrains.front().move;
        double without = 0.0, retrained = 0.0, kept = 0.0;
        for (std::size_t i = static_cast<std::size_t>(c.first) + 1; i < moves.size(); ++i) {
            without += c.kept.moves[i].without.meanErrorMm;
            kept += c.kept.moves[i].with.meanErrorMm;
            retrained += c.retrained.moves[i].with.meanErrorMm;
        }
        c.retrainedPct = 100.0 * (1.0 - retrained / without);
        c.keptPct = 100.0 * (1.0 - kept / without);
        EXPECT_NEAR(c.retrainedPct, *c.retrained.reductionAfterRetrainPct, 1e-9);
        return c;
    }
    /// The monitor's difference over its last full window after the last retraining (none: NaN).
    static double lastDifference(const CornerWorkResult& r) {
        const int window = CornerScenario{}.retraining.monitor.windowCorners;
        const int since = r.retrains.empty() ? 0 : r.retrains.back().move + 1;
        for (int i = static_cast<int>(r.checks.size()) - 1; i >= since; --i)
            if (r.checks[static_cast<std::size_t>(i)].corners >= window)
                return r.checks[static_cast<std::size_t>(i)].differenceFraction;
        return std::nan("");
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

TEST_F(CornerPaperResult, AVelocityGainDriftOfOneAndAHalfIsRetrainedForAtLeastFivePointsBetterThanKept) {
    const double threshold = CornerScenario{}.retraining.monitor.thresholdFraction;
    for (FeedAxis axis : {FeedAxis::Z, FeedAxis::X}) {
        SCOPED_TRACE(toString(axis));
        CornerDrift drift;
        drift.kind = DriveDriftKind::Gain;
        drift.axis = axis;
        drift.factor = 1.5;
        const Compared c = compare(drift, 3);
        ASSERT_EQ(c.retrained.driftAtMove, 40);
        ASSERT_GE(c.first, 40);  // no retraining before the drift, and one within the window after it
        ASSERT_LT(c.first, 50);
        const CornerRetrainEvent& e = c.retrained.retrains.front();
        EXPECT_TRUE(e.verdict.accepted) << e.reason;
        // The gain found is the drift's (within 1 %); the other drive's is left at 1.
        EXPECT_NEAR(axisFactors(e.identified.factors, axis).velocityGain, 1.5, 0.015) << e.reason;
        EXPECT_NEAR(axisFactors(e.identified.factors, axis == FeedAxis::X ? FeedAxis::Z : FeedAxis::X).velocityGain,
                    1.0, 0.01);
        // The figure: the retrained network at least 5 points better than the one kept.
        EXPECT_GE(c.retrainedPct, c.keptPct + 5.0) << c.retrainedPct << " against " << c.keptPct;
        // The controller's prediction is right again: within the threshold over the last full window.
        EXPECT_LT(std::abs(lastDifference(c.retrained)), threshold);
    }
}

TEST_F(CornerPaperResult, AFrictionOrInertiaDriftIsFoundAndThePredictionRightAgainWithoutLosingReduction) {
    const double threshold = CornerScenario{}.retraining.monitor.thresholdFraction;
    for (auto [kind, factor] : {std::pair{DriveDriftKind::Friction, 1.3}, std::pair{DriveDriftKind::Inertia, 1.5}}) {
        SCOPED_TRACE(toString(kind));
        CornerDrift drift;
        drift.kind = kind;
        drift.factor = factor;
        const Compared c = compare(drift, 3);
        ASSERT_GE(c.first, 40);
        ASSERT_LT(c.first, 50);
        const CornerRetrainEvent& e = c.retrained.retrains.front();
        EXPECT_GT(c.retrained.checks[static_cast<std::size_t>(c.first)].differenceFraction, threshold);
        // What drifted is found on Z (per-corner friction scatter 5 %), X is left alone.
        const double found =
            kind == DriveDriftKind::Friction ? e.identified.factors.z.friction : e.identified.factors.z.inertia;
        EXPECT_NEAR(found, factor, 0.1 * factor) << e.reason;
        EXPECT_NEAR(e.identified.factors.x.velocityGain, 1.0, 0.01);
        EXPECT_NEAR(e.identified.factors.z.velocityGain, 1.0, 0.01);
        EXPECT_TRUE(e.modelUpdated);
        EXPECT_LT(std::abs(lastDifference(c.retrained)), threshold);
        // Retrained or refused, the run does not lose reduction against the network kept (within the
        // half point a network retrained on 10 new corners varies by), and keeps half the error off.
        EXPECT_GE(c.retrainedPct, c.keptPct - 0.5) << c.retrainedPct << " against " << c.keptPct;
        EXPECT_GE(c.retrainedPct, 50.0);
    }
}

// The points of mean error a perfect retraining wins back after a drift: the best pulse of every move found
// again on the drifted drives against the nominal drives' best pulse kept, in % of the error without a pulse.
double perfectRetrainingPoints(const CornerScenario& s, const std::vector<CornerMove>& moves, DriveDriftKind kind,
                               FeedAxis axis, double factor) {
    const FeedDrivesConfig drifted = scaledDrives(s.drives, driftFactors(kind, axis, factor));
    double without = 0.0, kept = 0.0, best = 0.0;
    for (const CornerMove& m : moves) {
        const double nominal = findBestPulse(s.drives, s.cost, m, s.pulse, s.training.search).amplitudeV;
        const PulseOptimum o = findBestPulse(drifted, s.cost, m, s.pulse, s.training.search);
        without += o.without.meanErrorMm;
        best += o.with.meanErrorMm;
        kept += simulateCorner(drifted, s.cost, m, s.pulse, nominal).cost.meanErrorMm;
    }
    return 100.0 * (kept - best) / without;
}

TEST(CornerDriftPhysics, RegressionPinEvenAPerfectRetrainingWinsBackLittleAfterAFrictionOrInertiaDrift) {
    // Why the 5-point figure is shown on the gain and not on the friction or the inertia: over 20 moves of
    // seed 3, 1.5x the friction or the inertia of either drive wins back under 2 points to a perfect
    // retraining, 1.5x the velocity gain over 30 (DECISIONS, "Drift kinds").
    const CornerScenario s;
    const std::vector<CornerMove> moves = drawCornerMoves(s.xSpeeds, s.zSpeeds, 20, 3);
    for (FeedAxis axis : {FeedAxis::X, FeedAxis::Z})
        for (DriveDriftKind kind : {DriveDriftKind::Friction, DriveDriftKind::Inertia, DriveDriftKind::Gain}) {
            const double points = perfectRetrainingPoints(s, moves, kind, axis, 1.5);
            if (kind == DriveDriftKind::Gain)
                EXPECT_GT(points, 30.0) << toString(kind) << " " << toString(axis);
            else
                EXPECT_LT(points, 2.0) << toString(kind) << " " << toString(axis);
        }
}

// The 1v340-soft-drives preset (tests/app/corner/corner_soft_drives_test.cpp checks the file holds these values):
// the CNC's position loop at half the gain on both drives, the cross slide's velocity loop commissioned slow and
// critically damped, the pulse fired earlier for the slower position loop.
CornerScenario softDrives() {
    CornerScenario s;
    s.drives.x.positionGainPerS = 8.35;
    s.drives.z.positionGainPerS = 8.35;
    s.drives.x.velocityGainAPerRadPerS = 0.08;  // J / (Kp kt) = 50 ms
    s.drives.x.velocityIntegralTimeS = 0.2;     // damping 1: Ti = 4 J / (Kp kt)
    s.pulse.leadS = 0.06;
    return s;
}

// The mean error the best pulse of every move removes, in % of the error without a pulse.
double bestPulsesReductionPct(const CornerScenario& s, const std::vector<CornerMove>& moves) {
    double without = 0.0, with = 0.0;
    for (const CornerMove& m : moves) {
        const PulseOptimum o = findBestPulse(s.drives, s.cost, m, s.pulse, s.training.search);
        without += o.without.meanErrorMm;
        with += o.with.meanErrorMm;
    }
    return 100.0 * (1.0 - with / without);
}

TEST(CornerDriftPhysics, RegressionPinInertiaMovesTheBestPulseWhereTheVelocityLoopIsSlowAgainstThePulse) {
    // The pulse passes through the velocity loop of the drive it is added to, whose closed-loop time constant is
    // J / (Kp kt). On the soft drives it is 50 ms on X (75 ms at 1.5x the inertia), as long as the pulse: the
    // inertia reshapes what the pulse does, a perfect retraining wins back 29.0 points after 1.5x the X inertia
    // (20 moves of seed 3, measured on this simulator), and the best pulses still cut the error by 67.0 %
    // (paper: 69 %). The Z inertia, behind Z's unchanged 16.7 ms loop, moves it by 2.5 points.
    const CornerScenario soft = softDrives();
    const std::vector<CornerMove> moves = drawCornerMoves(soft.xSpeeds, soft.zSpeeds, 20, 3);
    EXPECT_GT(perfectRetrainingPoints(soft, moves, DriveDriftKind::Inertia, FeedAxis::X, 1.5), 15.0);
    EXPECT_LT(perfectRetrainingPoints(soft, moves, DriveDriftKind::Inertia, FeedAxis::Z, 1.5), 5.0);
    EXPECT_GT(bestPulsesReductionPct(soft, moves), 65.0);
}

TEST(CornerDriftPhysics, RegressionPinASlowButUnderdampedVelocityLoopLosesThePulsesEffect) {
    // Slowing the X velocity loop alone (0.15 A per rad/s, 27 ms) with the preset's 15 ms integral time leaves
    // the loop underdamped (damping 0.22): a perfect retraining wins back 6.5 points after 1.5x the inertia, but
    // the pulse then cuts the error by under 50 % (measured: 47 %). The soft drives keep the loop damped.
    CornerScenario slow;
    slow.drives.x.velocityGainAPerRadPerS = 0.15;
    const std::vector<CornerMove> moves = drawCornerMoves(slow.xSpeeds, slow.zSpeeds, 20, 3);
    EXPECT_GT(perfectRetrainingPoints(slow, moves, DriveDriftKind::Inertia, FeedAxis::X, 1.5), 5.0);
    EXPECT_LT(bestPulsesReductionPct(slow, moves), 50.0);
}

}  // namespace
}  // namespace tt::core
