// `trueturn corner train` and `trueturn corner` on the real binary (issue 15): the held-out result of
// paper 002 (the mean trajectory error falls by at least 60 % on moves of another seed; paper: 69 %),
// retraining when the Z friction rises by 30 % or the Z velocity gain by 50 %, the largest friction drift
// that once stopped the run (the identification compounded the friction until the model's Z could not
// break away), the JSON, and refusals.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>
#include <cmath>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

QSet<QString> keys(const QJsonObject& o) {
    const QStringList k = o.keys();
    return QSet<QString>(k.begin(), k.end());
}

class CornerCommand : public tt::test::CliTest {
protected:
    // One network for the suite: 200 training moves of seed 1 (about 2 s).
    static void SetUpTestSuite() {
        s_dir = new QTemporaryDir;
        s_net = s_dir->filePath(QStringLiteral("net.json"));
        const CliResult r =
            runTrueturn({QStringLiteral("corner"), QStringLiteral("train"), QStringLiteral("--seed"),
                         QStringLiteral("1"), QStringLiteral("--out"), s_net, QStringLiteral("--json")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        s_train = new QJsonObject(r.json());
    }
    static void TearDownTestSuite() {
        delete s_train;
        delete s_dir;
    }
    static QJsonObject work(const QStringList& extra) {
        QStringList args{QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--json")};
        args << extra;
        const CliResult r = runTrueturn(args);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return r.json();
    }

    static QTemporaryDir* s_dir;
    static QString s_net;
    static QJsonObject* s_train;
};

QTemporaryDir* CornerCommand::s_dir = nullptr;
QString CornerCommand::s_net;
QJsonObject* CornerCommand::s_train = nullptr;

TEST_F(CornerCommand, TrainReportsTheBestPulsesTheNetworkAndBothAxes) {
    const QJsonObject& t = *s_train;
    EXPECT_EQ(t.value(QStringLiteral("preset")).toString(), QStringLiteral("1v340-feed-drives"));
    EXPECT_EQ(t.value(QStringLiteral("moves")).toInt(), 200);
    EXPECT_EQ(t.value(QStringLiteral("axis")).toString(), QStringLiteral("x"));
    EXPECT_GT(t.value(QStringLiteral("best_pulses")).toObject().value(QStringLiteral("reduction_pct")).toDouble(),
              65.0);
    const QJsonObject net = t.value(QStringLiteral("network")).toObject();
    EXPECT_EQ(net.value(QStringLiteral("hidden")).toInt(), 10);
    EXPECT_LE(net.value(QStringLiteral("best_epoch")).toInt(), net.value(QStringLiteral("epochs")).toInt());
    EXPECT_LT(net.value(QStringLiteral("validation_rms_v")).toDouble(), 0.05);
    // Paper 002: correcting X reaches a given reduction with less amplitude than correcting Z. Here at
    // about the same mean amplitude the X pulse removes clearly more of the error.
    const QJsonObject cmp = t.value(QStringLiteral("axis_comparison")).toObject();
    const QJsonObject x = cmp.value(QStringLiteral("x")).toObject();
    const QJsonObject z = cmp.value(QStringLiteral("z")).toObject();
    EXPECT_GT(x.value(QStringLiteral("reduction_pct")).toDouble(),
              z.value(QStringLiteral("reduction_pct")).toDouble() + 5.0);
}

TEST_F(CornerCommand, HeldOutMovesOfAnotherSeedLoseAtLeastSixtyPercentInTheIssuesJson) {
    const QJsonObject j =
        work({QStringLiteral("--seed"), QStringLiteral("2"), QStringLiteral("--moves"), QStringLiteral("100")});
    EXPECT_EQ(keys(j),
              (QSet<QString>{QStringLiteral("moves"), QStringLiteral("mean_error_mm"), QStringLiteral("reduction_pct"),
                             QStringLiteral("retrain_events"), QStringLiteral("reduction_after_retrain_pct"),
                             QStringLiteral("drift"), QStringLiteral("monitor")}));
    EXPECT_TRUE(j.value(QStringLiteral("drift")).isNull());
    const QJsonObject monitor = j.value(QStringLiteral("monitor")).toObject();
    EXPECT_EQ(monitor.value(QStringLiteral("threshold_pct")).toDouble(), 1.5);  // the preset's
    EXPECT_EQ(monitor.value(QStringLiteral("window_corners")).toInt(), 10);
    EXPECT_LT(std::abs(monitor.value(QStringLiteral("last_difference_pct")).toDouble()), 1.5);
    const QJsonArray moves = j.value(QStringLiteral("moves")).toArray();
    ASSERT_EQ(moves.size(), 100);
    double without = 0.0;
    double with = 0.0;
    for (const QJsonValue& v : moves) {
        const QJsonObject m = v.toObject();
        EXPECT_EQ(keys(m), (QSet<QString>{QStringLiteral("vx1"), QStringLiteral("vz1"), QStringLiteral("vx2"),
                                          QStringLiteral("vz2"), QStringLiteral("error_without_mm"),
                                          QStringLiteral("error_with_mm"), QStringLiteral("amplitude_v")}));
        for (const QString& k :
             {QStringLiteral("vx1"), QStringLiteral("vz1"), QStringLiteral("vx2"), QStringLiteral("vz2")}) {
            EXPECT_GE(m.value(k).toDouble(), 0.5);
            EXPECT_LE(m.value(k).toDouble(), 9.0);
        }
        EXPECT_LE(std::abs(m.value(QStringLiteral("amplitude_v")).toDouble()), 0.5);
        without += m.value(QStringLiteral("error_without_mm")).toDouble();
        with += m.value(QStringLiteral("error_with_mm")).toDouble();
    }
    const QJsonObject mean = j.value(QStringLiteral("mean_error_mm")).toObject();
    EXPECT_NEAR(mean.value(QStringLiteral("without")).toDouble(), without / 100.0, 1e-12);
    EXPECT_NEAR(mean.value(QStringLiteral("with")).toDouble(), with / 100.0, 1e-12);
    const double reduction = j.value(QStringLiteral("reduction_pct")).toDouble();
    EXPECT_NEAR(reduction, 100.0 * (1.0 - with / without), 1e-9);
    EXPECT_GE(reduction, 60.0);  // paper 002: 0.04673 -> 0.01453 mm, -69 %
    EXPECT_TRUE(j.value(QStringLiteral("retrain_events")).toArray().isEmpty());
    EXPECT_TRUE(j.value(QStringLiteral("reduction_after_retrain_pct")).isNull());
}

TEST_F(CornerCommand, ThirtyPercentMoreZFrictionIsDetectedAndRetrainedFor) {
    const QJsonObject j = work({QStringLiteral("--seed"), QStringLiteral("3"), QStringLiteral("--moves"),
                                QStringLiteral("80"), QStringLiteral("--drift"), QStringLiteral("1.3")});
    const QJsonArray events = j.value(QStringLiteral("retrain_events")).toArray();
    ASSERT_FALSE(events.isEmpty());
    const QJsonObject first = events.first().toObject();
    EXPECT_EQ(keys(first), (QSet<QString>{QStringLiteral("move"), QStringLiteral("reason"), QStringLiteral("accepted"),
                                          QStringLiteral("failure"), QStringLiteral("model_updated"),
                                          QStringLiteral("identified"), QStringLiteral("validation_cost_mm")}));
    const QJsonObject z = first.value(QStringLiteral("identified")).toObject().value(QStringLiteral("z")).toObject();
    EXPECT_EQ(keys(z), (QSet<QString>{QStringLiteral("friction"), QStringLiteral("inertia"), QStringLiteral("gain"),
                                      QStringLiteral("encoder_rms_um")}));
    EXPECT_NEAR(z.value(QStringLiteral("friction")).toDouble(), 1.3, 0.15);
    // Taken or refused, the event says so; a refused one names why.
    EXPECT_EQ(first.value(QStringLiteral("failure")).isNull(), first.value(QStringLiteral("accepted")).toBool());
    const QJsonObject drift = j.value(QStringLiteral("drift")).toObject();
    EXPECT_EQ(drift.value(QStringLiteral("kind")).toString(), QStringLiteral("friction"));
    EXPECT_EQ(drift.value(QStringLiteral("axis")).toString(), QStringLiteral("z"));
    EXPECT_EQ(drift.value(QStringLiteral("at_move")).toInt(), 40);
    // The drift starts at move 40; the monitor's window is 10 corners.
    EXPECT_GE(first.value(QStringLiteral("move")).toInt(), 40);
    EXPECT_LT(first.value(QStringLiteral("move")).toInt(), 50);
    EXPECT_TRUE(first.value(QStringLiteral("reason")).toString().contains(QStringLiteral("above the predicted")))
        << qPrintable(first.value(QStringLiteral("reason")).toString());
    EXPECT_GE(j.value(QStringLiteral("reduction_after_retrain_pct")).toDouble(), 50.0);
}

TEST_F(CornerCommand, AVelocityGainDriftIsIdentifiedAndRetrainedFor) {
    const QJsonObject j = work({QStringLiteral("--seed"), QStringLiteral("3"), QStringLiteral("--moves"),
                                QStringLiteral("80"), QStringLiteral("--drift"), QStringLiteral("1.5"),
                                QStringLiteral("--drift-kind"), QStringLiteral("gain")});
    EXPECT_EQ(j.value(QStringLiteral("drift")).toObject().value(QStringLiteral("kind")).toString(),
              QStringLiteral("gain"));
    const QJsonArray events = j.value(QStringLiteral("retrain_events")).toArray();
    ASSERT_FALSE(events.isEmpty());
    const QJsonObject first = events.first().toObject();
    EXPECT_TRUE(first.value(QStringLiteral("accepted")).toBool())
        << qPrintable(first.value(QStringLiteral("reason")).toString());
    const QJsonObject z = first.value(QStringLiteral("identified")).toObject().value(QStringLiteral("z")).toObject();
    EXPECT_NEAR(z.value(QStringLiteral("gain")).toDouble(), 1.5, 0.015);
    const QJsonObject cost = first.value(QStringLiteral("validation_cost_mm")).toObject();
    EXPECT_LT(cost.value(QStringLiteral("candidate")).toDouble(), cost.value(QStringLiteral("kept")).toDouble());
    // The prediction is right again after the retraining.
    EXPECT_LT(
        std::abs(j.value(QStringLiteral("monitor")).toObject().value(QStringLiteral("last_difference_pct")).toDouble()),
        1.5);
}

TEST_F(CornerCommand, TheLargestFrictionDriftRunsWithRetraining) {
    // Before: "the tool did not pass the end of the control interval within 5 s" (exit 1), seed 7 from 2.5 on.
    const QJsonObject j = work({QStringLiteral("--seed"), QStringLiteral("7"), QStringLiteral("--moves"),
                                QStringLiteral("80"), QStringLiteral("--drift"), QStringLiteral("3")});
    ASSERT_FALSE(j.value(QStringLiteral("retrain_events")).toArray().isEmpty());
    for (const QJsonValue& v : j.value(QStringLiteral("retrain_events")).toArray()) {
        const QJsonObject z =
            v.toObject().value(QStringLiteral("identified")).toObject().value(QStringLiteral("z")).toObject();
        // Never above the friction at which the model's Z could no longer break away (24 / 5 = 4.8).
        EXPECT_LT(z.value(QStringLiteral("friction")).toDouble(), 0.9 * 24.0 / 5.0);
    }
    EXPECT_GE(j.value(QStringLiteral("reduction_pct")).toDouble(), 40.0);
}

TEST_F(CornerCommand, PrintsTextWithoutJson) {
    const CliResult r = runTrueturn(
        {QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--moves"), QStringLiteral("5")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Mean trajectory error"))) << qPrintable(r.out);
}

TEST_F(CornerCommand, RefusesBadOptionsFilesAndPresets) {
    expectRefused({QStringLiteral("corner"), QStringLiteral("train")}, QStringLiteral("--out: is required"));
    expectRefused(
        {QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--drift"), QStringLiteral("5")},
        QStringLiteral("--drift: 5 is outside 0.5 .. 3"));
    expectRefused({QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--drift"),
                   QStringLiteral("0.4"), QStringLiteral("--drift-kind"), QStringLiteral("inertia")},
                  QStringLiteral("--drift: 0.4 is outside 0.5 .. 3"));
    expectRefused(
        {QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--moves"), QStringLiteral("0")},
        QStringLiteral("--moves: 0 is outside 1 .. 10000"));
    expectRefused({QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--drift-kind"),
                   QStringLiteral("load")},
                  QStringLiteral("--drift-kind: 'load' is not one of friction, gain, inertia"));
    expectRefused(
        {QStringLiteral("corner"), QStringLiteral("--net"), s_net, QStringLiteral("--drift-axis"), QStringLiteral("y")},
        QStringLiteral("--drift-axis: 'y' is not one of x, z"));
    // A carriage with 10 N·m of static friction against 24 N·m at its current limit: three times that
    // could never move, and the run is refused before it starts.
    const QString sticky =
        write(QStringLiteral("sticky.json"), R"({"name": "sticky", "drives": {"z": {"static_friction_nm": 10}}})");
    expectRefused({QStringLiteral("corner"), QStringLiteral("--preset"), sticky, QStringLiteral("--net"), s_net,
                   QStringLiteral("--drift"), QStringLiteral("3")},
                  QStringLiteral("--drift: Z: static friction 30 N·m is not below the torque at the current limit "
                                 "(24 N·m): the motor could never break away"));
    expectRefused({QStringLiteral("corner"), QStringLiteral("--net"), path(QStringLiteral("none.json"))},
                  QStringLiteral("cannot read"));
    const QString other = write(QStringLiteral("other.json"), R"({"format": "something else"})");
    expectRefused({QStringLiteral("corner"), QStringLiteral("--net"), other},
                  QStringLiteral("format: not a TrueTurn corrective-pulse network"));
    const QString preset =
        write(QStringLiteral("preset.json"), R"({"name": "bad", "speeds": {"z_rad_per_s": [0.2, 9]}})");
    expectRefused({QStringLiteral("corner"), QStringLiteral("train"), QStringLiteral("--preset"), preset,
                   QStringLiteral("--out"), path(QStringLiteral("x.json"))},
                  QStringLiteral("speeds.z_rad_per_s: must lie within 0.5 .. 9 rad/s"));
}

}  // namespace
