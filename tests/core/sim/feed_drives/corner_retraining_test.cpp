// The guard of the retraining (paper 002): a retrained network replaces the one in use only when it does
// better on held-out moves and its pulses stay within the drive's limits; a retraining that fails is
// reported and leaves the network in use, its training set and the model as they were.
#include <gtest/gtest.h>

#include "core/sim/feed_drives/corner_work_run.h"

namespace tt::core {
namespace {

// A network whose output is `amplitudeV` for every move.
CorrectiveNet constantNet(double amplitudeV) {
    NetWeights w;
    w.hidden = Eigen::MatrixXd::Zero(CorrectiveNet::kPaperHidden, CorrectiveNet::kInputs);
    w.hiddenBias = Eigen::VectorXd::Zero(CorrectiveNet::kPaperHidden);
    w.output = Eigen::VectorXd::Zero(CorrectiveNet::kPaperHidden);
    w.outputBias = amplitudeV;
    return CorrectiveNet(w, NetNormalisation{});
}

TEST(CandidateVerdict, AcceptsOnlyALowerValidationCost) {
    const CornerScenario s;
    const std::vector<CornerMove> moves = drawCornerMoves(s.xSpeeds, s.zSpeeds, 8, 21);
    // The best pulses on this preset average about 0.13 V on X (README); none at all leaves the error,
    // and the full −0.5 V pushes X the wrong way.
    const CandidateVerdict better =
        judgeCandidate(s.drives, s.cost, s.pulse, constantNet(-0.5), constantNet(0.12), moves);
    EXPECT_TRUE(better.accepted) << better.failure;
    EXPECT_LT(better.candidateCostMm, better.keptCostMm);
    const CandidateVerdict worse =
        judgeCandidate(s.drives, s.cost, s.pulse, constantNet(0.12), constantNet(-0.5), moves);
    EXPECT_FALSE(worse.accepted);
    EXPECT_GT(worse.candidateCostMm, worse.keptCostMm);
    EXPECT_NE(worse.failure.find("is not below the"), std::string::npos) << worse.failure;
    // The same network is not better than itself.
    EXPECT_FALSE(judgeCandidate(s.drives, s.cost, s.pulse, constantNet(0.12), constantNet(0.12), moves).accepted);
}

TEST(CandidateVerdict, RefusesPulsesThatDriveTheMotorToItsCurrentLimit) {
    // X with a 3 A current limit: 0.5 V asks 10 rad/s more of a velocity loop of 0.6 A per rad/s, i.e.
    // 6 A on top of the friction current: the limit (paper 002: a large amplitude "causes shock currents").
    CornerScenario s;
    s.drives.x.currentLimitA = 3.0;
    const std::vector<CornerMove> moves = drawCornerMoves(s.xSpeeds, s.zSpeeds, 4, 21);
    const CandidateVerdict v = judgeCandidate(s.drives, s.cost, s.pulse, constantNet(0.0), constantNet(0.5), moves);
    EXPECT_FALSE(v.accepted);
    EXPECT_DOUBLE_EQ(v.candidatePeakCurrentA, 3.0);
    EXPECT_EQ(v.failure, "its pulses drive the X motor to its current limit of 3 A");
    // A 0.05 V pulse asks 0.6 A more: within the limit.
    EXPECT_LT(
        judgeCandidate(s.drives, s.cost, s.pulse, constantNet(0.0), constantNet(0.05), moves).candidatePeakCurrentA,
        3.0);
}

TEST(CornerRetraining, AFailedRetrainingIsReportedAndKeepsTheNetworkTheSetAndTheModel) {
    const CornerScenario s;
    CorrectiveNet net = constantNet(0.1);
    // A training move from a network file with a speed beyond the pulse's 0.5 .. 9 rad/s: re-targeting it fails.
    std::vector<NetSample> set(12, NetSample{{2.0, 3.0, 4.0, 5.0}, 0.1, 1.0});
    set[5].speedsRadPerS[3] = 12.0;
    const std::vector<NetSample> setBefore = set;
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = kCornerRecordEvery;
    std::vector<RecordedCorner> corners;
    const FeedDrivesConfig machine = scaledDrives(s.drives, driftFactors(DriveDriftKind::Gain, FeedAxis::Z, 1.5));
    for (const CornerMove& m : drawCornerMoves(s.xSpeeds, s.zSpeeds, 4, 5))
        corners.push_back({m, 0.1, simulateCorner(machine, s.cost, m, s.pulse, 0.1, options).trace});
    FeedDrivesFactors model;
    const CornerRetrainEvent e = retrainOnCorners(s, model, net, set, corners, 9, "asked for");
    EXPECT_FALSE(e.verdict.accepted);
    EXPECT_NE(e.verdict.failure.find("the retraining failed: Vz2 12 rad/s is outside"), std::string::npos)
        << e.verdict.failure;
    EXPECT_NE(e.reason.find("the network in use and the model are kept"), std::string::npos) << e.reason;
    EXPECT_EQ(net.weights().outputBias, 0.1);
    EXPECT_EQ(net.record().retrainings, 0);
    ASSERT_EQ(set.size(), setBefore.size());
    EXPECT_EQ(set[5].speedsRadPerS[3], 12.0);
    EXPECT_EQ(model.z.velocityGain, 1.0);
    // The identification itself had found the drift.
    EXPECT_NEAR(e.identified.factors.z.velocityGain, 1.5, 0.01);
}

}  // namespace
}  // namespace tt::core
