// `trueturn corner` on the 1v340-soft-drives preset (issue 25, item 3): the CNC's position loop at half the gain
// and the cross slide's velocity loop slow (50 ms) and damped, so the inertia at the X motor changes what the
// pulse does. After 1.5x the X inertia from move 40 the network the controller retrains cuts the error by at
// least 5 points more than the network kept, over the same moves after the first retraining (the issue's
// figure; measured 50.8 / 41.9 % on seed 3 and 56.9 / 45.6 % on seed 7), the identification finds the inertia,
// and the monitor's difference is back under its threshold. Without a drift the monitor stays quiet.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "cli_test.h"
#include "config/corner_config.h"

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

const QString kPreset = QStringLiteral("1v340-soft-drives");

class SoftDrives : public ::testing::Test {
protected:
    // One network for the suite: 200 training moves of seed 1 on the preset.
    static void SetUpTestSuite() {
        s_dir = new QTemporaryDir;
        s_net = s_dir->filePath(QStringLiteral("soft.json"));
        const CliResult r = runTrueturn({QStringLiteral("corner"), QStringLiteral("train"), QStringLiteral("--preset"),
                                         kPreset, QStringLiteral("--seed"), QStringLiteral("1"),
                                         QStringLiteral("--out"), s_net, QStringLiteral("--json")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    }
    static void TearDownTestSuite() { delete s_dir; }

    static QJsonObject work(const QStringList& extra) {
        QStringList args{QStringLiteral("corner"), QStringLiteral("--preset"), kPreset, QStringLiteral("--net"), s_net,
                         QStringLiteral("--json")};
        args << extra;
        const CliResult r = runTrueturn(args);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return r.json();
    }

    /// % of the error without a pulse that the pulse removed over the moves after `first`.
    static double reductionAfter(const QJsonObject& run, int first) {
        const QJsonArray moves = run.value(QStringLiteral("moves")).toArray();
        double without = 0.0, with = 0.0;
        for (qsizetype i = first + 1; i < moves.size(); ++i) {
            without += moves[i].toObject().value(QStringLiteral("error_without_mm")).toDouble();
            with += moves[i].toObject().value(QStringLiteral("error_with_mm")).toDouble();
        }
        return 100.0 * (1.0 - with / without);
    }

    /// A drift of `kind` x1.5 on X from move 40 of 120, with retraining and with the network kept: the retrained
    /// network's reduction after the first retraining at least 5 points above the kept one's; returns the run.
    static QJsonObject expectRetrainingWinsFivePoints(const QString& kind, int seed) {
        const QStringList drift{QStringLiteral("--seed"),       QString::number(seed),
                                QStringLiteral("--moves"),      QStringLiteral("120"),
                                QStringLiteral("--drift"),      QStringLiteral("1.5"),
                                QStringLiteral("--drift-kind"), kind,
                                QStringLiteral("--drift-axis"), QStringLiteral("x")};
        const QJsonObject retrained = work(drift);
        const QJsonObject kept = work(drift + QStringList{QStringLiteral("--no-retrain")});
        EXPECT_TRUE(kept.value(QStringLiteral("retrain_events")).toArray().isEmpty());
        const QJsonArray events = retrained.value(QStringLiteral("retrain_events")).toArray();
        if (events.isEmpty()) {
            ADD_FAILURE() << "no retraining";
            return retrained;
        }
        const int first = events.first().toObject().value(QStringLiteral("move")).toInt();
        EXPECT_GE(first, 40);  // nothing before the drift
        const double withRetraining = reductionAfter(retrained, first);
        EXPECT_NEAR(withRetraining, retrained.value(QStringLiteral("reduction_after_retrain_pct")).toDouble(), 1e-9);
        EXPECT_GE(withRetraining, reductionAfter(kept, first) + 5.0)
            << withRetraining << " % against " << reductionAfter(kept, first) << " % kept";
        return retrained;
    }

    /// The X factor of `what` the last accepted retraining identified (NaN without one).
    static double lastAcceptedX(const QJsonObject& run, const QString& what) {
        double found = std::nan("");
        for (const QJsonValue& e : run.value(QStringLiteral("retrain_events")).toArray())
            if (e.toObject().value(QStringLiteral("accepted")).toBool())
                found = e.toObject()
                            .value(QStringLiteral("identified"))
                            .toObject()
                            .value(QStringLiteral("x"))
                            .toObject()
                            .value(what)
                            .toDouble();
        return found;
    }

    /// The monitor's difference over its last full window, against its threshold.
    static void expectPredictionRightAgain(const QJsonObject& run) {
        const QJsonObject monitor = run.value(QStringLiteral("monitor")).toObject();
        ASSERT_FALSE(monitor.value(QStringLiteral("last_difference_pct")).isNull());
        EXPECT_LT(std::abs(monitor.value(QStringLiteral("last_difference_pct")).toDouble()),
                  monitor.value(QStringLiteral("threshold_pct")).toDouble());
    }

    static QTemporaryDir* s_dir;
    static QString s_net;
};

QTemporaryDir* SoftDrives::s_dir = nullptr;
QString SoftDrives::s_net;

TEST_F(SoftDrives, ThePresetIsTheSlowCrossSlideTheDriftPhysicsTestsPin) {
    // tests/core/sim/feed_drives/corner_paper_result_test.cpp, softDrives(): the same values.
    const tt::core::CornerScenario s = tt::config::loadCornerScenario(kPreset);
    EXPECT_EQ(s.drives.x.positionGainPerS, 8.35);
    EXPECT_EQ(s.drives.z.positionGainPerS, 8.35);
    EXPECT_EQ(s.drives.x.velocityGainAPerRadPerS, 0.08);
    EXPECT_EQ(s.drives.x.velocityIntegralTimeS, 0.2);
    EXPECT_EQ(s.pulse.leadS, 0.06);
    EXPECT_EQ(s.pulse.durationS, 0.05);
    EXPECT_EQ(s.pulse.axis, tt::core::FeedAxis::X);
    EXPECT_EQ(s.retraining.monitor.thresholdFraction, 0.03);
    const tt::core::CornerScenario paper;  // everything else is the 1v340-feed-drives machine
    EXPECT_EQ(s.drives.x.inertiaKgM2, paper.drives.x.inertiaKgM2);
    EXPECT_EQ(s.drives.z.velocityGainAPerRadPerS, paper.drives.z.velocityGainAPerRadPerS);
    EXPECT_EQ(s.machine.frictionScatter, paper.machine.frictionScatter);
}

TEST_F(SoftDrives, WithoutADriftTheMonitorStaysQuietAndThePulseCutsHalfTheError) {
    const QJsonObject j =
        work({QStringLiteral("--seed"), QStringLiteral("2"), QStringLiteral("--moves"), QStringLiteral("100")});
    EXPECT_TRUE(j.value(QStringLiteral("retrain_events")).toArray().isEmpty());
    EXPECT_GE(j.value(QStringLiteral("reduction_pct")).toDouble(), 50.0);  // measured 55.9 %
}

TEST_F(SoftDrives, OneAndAHalfTimesTheCrossSlidesInertiaIsRetrainedForAtLeastFivePointsBetterThanKept) {
    for (int seed : {3, 7}) {
        SCOPED_TRACE(seed);
        const QJsonObject run = expectRetrainingWinsFivePoints(QStringLiteral("inertia"), seed);
        EXPECT_NEAR(lastAcceptedX(run, QStringLiteral("inertia")), 1.5, 0.05);
        expectPredictionRightAgain(run);
    }
}

TEST_F(SoftDrives, OneAndAHalfTimesTheCrossSlidesVelocityGainIsRetrainedForAtLeastFivePointsBetterThanKept) {
    const QJsonObject run = expectRetrainingWinsFivePoints(QStringLiteral("gain"), 3);
    EXPECT_NEAR(lastAcceptedX(run, QStringLiteral("gain")), 1.5, 0.015);
    expectPredictionRightAgain(run);
}

}  // namespace
