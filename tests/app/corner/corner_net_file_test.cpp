// The network file of `trueturn corner train --out`: a trained network round-trips through JSON bit
// for bit (issue 15), and so do awkward doubles; a broken file is refused with the field named.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cstring>
#include <limits>

#include "cli_runner.h"
#include "config/corrective_net_json.h"

namespace tt::config {
namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    ASSERT_EQ(a.size(), b.size());
    for (Eigen::Index i = 0; i < a.size(); ++i)
        EXPECT_TRUE(sameBits(a(i), b(i))) << i << ": " << a(i) << " vs " << b(i);
}

TEST(CornerNetFile, ATrainedNetworkRoundTripsBitExactly) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("net.json"));
    const test::CliResult r =
        test::runTrueturn({QStringLiteral("corner"), QStringLiteral("train"), QStringLiteral("--moves"),
                           QStringLiteral("30"), QStringLiteral("--out"), path});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    const CornerNetFile loaded = cornerNetFromBytes(bytes);
    EXPECT_EQ(cornerNetToBytes(loaded), bytes);  // saving what was loaded gives the same file
    const CornerNetFile again = cornerNetFromBytes(cornerNetToBytes(loaded));
    expectSameBits(again.net.weights().flatten(), loaded.net.weights().flatten());
    EXPECT_EQ(loaded.net.weights().hiddenCount(), 10);
    EXPECT_EQ(loaded.samples.size(), 30u);
    EXPECT_EQ(loaded.preset, "1v340-feed-drives");
    EXPECT_EQ(loaded.pulse.leadS, 0.028);
    EXPECT_EQ(loaded.net.record().trainingLoss.size(), static_cast<std::size_t>(loaded.net.record().epochs));
    for (const core::NetSample& s : loaded.samples)
        EXPECT_TRUE(sameBits(loaded.net.amplitudeV(s.speedsRadPerS), again.net.amplitudeV(s.speedsRadPerS)));
}

TEST(CornerNetFile, AwkwardDoublesRoundTripBitExactly) {
    const double awkward[] = {0.1,
                              1.0 / 3.0,
                              -2.0 / 7.0,
                              1e-300,
                              std::numeric_limits<double>::denorm_min(),
                              std::numeric_limits<double>::max(),
                              123456789.123456789,
                              -1.0 / 3.0,
                              5e-324 * 3,
                              1.0};
    core::NetWeights w;
    w.hidden = Eigen::MatrixXd::Zero(3, 4);
    w.hiddenBias = Eigen::VectorXd::Zero(3);
    w.output = Eigen::VectorXd::Zero(3);
    int k = 0;
    for (Eigen::Index r = 0; r < 3; ++r)
        for (Eigen::Index c = 0; c < 4; ++c)
            w.hidden(r, c) = awkward[k++ % 10];
    w.hiddenBias << 0.7, -1e-5, 2.5e-17;
    w.output << -1e-310, 6.02214076e23, 0.30000000000000004;
    w.outputBias = 9007199254740993.0;
    core::NetNormalisation n;
    n.outputOffset = -0.123456789012345678;
    n.outputScale = 0.0987654321;
    const CornerNetFile file{core::CorrectiveNet(w, n), {}, "test", {{{0.5, 9.0, 1.0 / 3.0, 4.75}, 0.1 + 0.2, 0.3}}};
    const CornerNetFile back = cornerNetFromBytes(cornerNetToBytes(file));
    expectSameBits(back.net.weights().flatten(), w.flatten());
    EXPECT_TRUE(sameBits(back.net.normalisation().outputOffset, n.outputOffset));
    EXPECT_TRUE(sameBits(back.net.normalisation().outputScale, n.outputScale));
    EXPECT_TRUE(sameBits(back.samples[0].amplitudeV, 0.1 + 0.2));
    EXPECT_TRUE(sameBits(back.samples[0].speedsRadPerS[2], 1.0 / 3.0));
}

TEST(CornerNetFile, NegativeZeroComesBackAsZeroWithTheSameAmplitude) {
    // JSON as Qt reads it has one zero: a weight of −0 is read as +0. Every product and sum of the
    // network gives the same bits with either (w·u is ±0 and vanishes in any sum with a non-zero term;
    // σ(±0) = 0.5), so the amplitudes stay bit-identical.
    core::NetWeights w;
    w.hidden = Eigen::MatrixXd::Constant(2, 4, 0.25);
    w.hidden(1, 2) = -0.0;
    w.hiddenBias = Eigen::VectorXd::Zero(2);
    w.output = Eigen::Vector2d(-0.0, 0.5);
    const CornerNetFile file{core::CorrectiveNet(w, {}), {}, "test", {}};
    const CornerNetFile back = cornerNetFromBytes(cornerNetToBytes(file));
    EXPECT_EQ(back.net.weights().hidden(1, 2), 0.0);
    for (const core::NetInputs& v : {core::NetInputs{0.5, 9.0, 4.75, 1.0}, core::NetInputs{4.75, 4.75, 4.75, 4.75}})
        EXPECT_TRUE(sameBits(back.net.amplitudeV(v), file.net.amplitudeV(v)));
}

TEST(CornerNetFile, RefusesBrokenFilesNamingTheField) {
    EXPECT_THROW(cornerNetFromBytes("{"), std::invalid_argument);
    core::NetWeights w;
    w.hidden = Eigen::MatrixXd::Ones(2, 4);
    w.hiddenBias = Eigen::VectorXd::Zero(2);
    w.output = Eigen::VectorXd::Ones(2);
    QJsonObject json = cornerNetToJson({core::CorrectiveNet(w, {}), {}, "x", {}});
    QJsonObject network = json.value(QStringLiteral("network")).toObject();
    network.insert(QStringLiteral("hidden_bias"), QJsonArray{1.0});
    json.insert(QStringLiteral("network"), network);
    try {
        cornerNetFromJson(json);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "network.hidden_bias: must hold 2 numbers");
    }
}

}  // namespace
}  // namespace tt::config
