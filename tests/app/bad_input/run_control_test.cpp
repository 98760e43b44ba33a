#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QThread>
#include <csignal>

#include "cli_test.h"
#include "tests/support/patient_wait.h"

// Bad input to a simulated run (issue 17, items 2 and 4): its pacing speed, a resumed run's stored parts,
// which run --resume continues, and Ctrl-C in the middle of a stored run.

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

class RunControl : public tt::test::CliTest {
protected:
    /// Runs `statement` on the SQLite file `db` with the sqlite3 shell; returns its output, trimmed.
    static QString sql(const QString& db, const QString& statement) {
        QProcess sqlite;
        sqlite.start(QStringLiteral("sqlite3"), {db, statement});
        EXPECT_TRUE(sqlite.waitForFinished(tt::test::kPatientWaitMs));
        EXPECT_EQ(sqlite.exitCode(), 0) << qPrintable(QString::fromUtf8(sqlite.readAllStandardError()));
        return QString::fromUtf8(sqlite.readAllStandardOutput()).trimmed();
    }

    /// A complete stored run of `parts` parts (no warm-up) in `db`; fails the test when it does not run.
    static void storeRun(const QString& db, int parts) {
        const CliResult r = runTrueturn({QStringLiteral("simulate"), QStringLiteral("--parts"), QString::number(parts),
                                         QStringLiteral("--warmup"), QStringLiteral("0"), QStringLiteral("--db"), db,
                                         QStringLiteral("--json")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    }
};

TEST_F(RunControl, ASpeedOutsideItsRangeIsRefusedWithTheRange) {
    // 1e-9 waited 1e9 s per simulated second; 1e-300 made every wait infinite (core/run/run_limits.h).
    for (const char* speed : {"1e-9", "1e-300", "0.5"})
        expectRefused({QStringLiteral("simulate"), QStringLiteral("--speed"), QString::fromLatin1(speed)},
                      QStringLiteral("0 (as fast as possible) or 1 .. 1e+09"));
    expectRefused({QStringLiteral("simulate"), QStringLiteral("--speed"), QStringLiteral("1e300")},
                  QStringLiteral("--speed: 1e+300 is outside 0 .. 1e+09"));
}

TEST_F(RunControl, AResumedRunAskingForTooManyPartsIsRefusedBeforeItStarts) {
    // The settings stored with the run were edited to 1e18 parts: the resume used to run for ever.
    const QString db = path(QStringLiteral("history.sqlite"));
    storeRun(db, 100);
    sql(db, QStringLiteral("UPDATE runs SET status = 'running', settings = json_set(settings, '$.request.end_part', "
                           "1000000000000000000)"));
    expectRefused({QStringLiteral("simulate"), QStringLiteral("--db"), db, QStringLiteral("--resume")},
                  QStringLiteral("end_part: 1000000000000000000 is outside 1 .. 11000000"));
    sql(db, QStringLiteral("UPDATE runs SET settings = json_set(settings, '$.request.end_part', 100, "
                           "'$.request.warmup_parts', 5000000)"));
    expectRefused({QStringLiteral("simulate"), QStringLiteral("--db"), db, QStringLiteral("--resume")},
                  QStringLiteral("warmup_parts: 5000000 is outside 0 .. 1000000"));
}

TEST_F(RunControl, ResumeNamesTheRunToContinue) {
    const QString db = path(QStringLiteral("two.sqlite"));
    storeRun(db, 100);
    storeRun(db, 100);
    sql(db, QStringLiteral("UPDATE runs SET status = 'running' WHERE id = 1"));
    const QStringList resume{QStringLiteral("simulate"), QStringLiteral("--db"), db, QStringLiteral("--resume")};
    // The newest (2) is complete; run 1 is named.
    expectRefused(resume, QStringLiteral("the last run (2) is already complete"));
    expectRefused(resume + QStringList{QStringLiteral("7")},
                  QStringLiteral("there is no run 7; the history holds run(s) 2 (complete, 100 parts), 1 (running, "
                                 "100 parts)"));
    expectRefused(resume + QStringList{QStringLiteral("x")},
                  QStringLiteral("--resume N: the run number 'x' is not a whole number"));
    expectRefused(resume + QStringList{QStringLiteral("0")},
                  QStringLiteral("--resume N: the run number 0 is outside 1 .. 9007199254740992"));
    const CliResult r = runTrueturn(resume + QStringList{QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_EQ(r.json().value(QStringLiteral("run_id")).toInt(), 1);
    EXPECT_EQ(sql(db, QStringLiteral("SELECT group_concat(status) FROM (SELECT status FROM runs ORDER BY id)")),
              QStringLiteral("complete,complete"));
    const CliResult again =
        runTrueturn({QStringLiteral("simulate"), QStringLiteral("--db"), db, QStringLiteral("--resume=1")});
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_TRUE(again.err.contains(QStringLiteral("run 1 (1) is already complete"))) << qPrintable(again.err);
}

TEST_F(RunControl, CtrlCStopsAfterAPartAndTheRunResumesWithEveryPartOnce) {
    constexpr int parts = 300;
    const QString db = path(QStringLiteral("interrupted.sqlite"));
    QProcess process;
    // Paced at 10 000 x (about 40 ms a part) with the progress on stderr.
    process.start(
        QStringLiteral(TRUETURN_EXE),
        {QStringLiteral("simulate"), QStringLiteral("--parts"), QString::number(parts), QStringLiteral("--warmup"),
         QStringLiteral("0"), QStringLiteral("--db"), db, QStringLiteral("--speed"), QStringLiteral("10000"),
         QStringLiteral("--progress"), QStringLiteral("--json")});
    ASSERT_TRUE(process.waitForStarted());
    QElapsedTimer timer;
    timer.start();
    QByteArray err;
    while (!err.contains("closed loop: part") && timer.elapsed() < 60000 && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        err += process.readAllStandardError();
    }
    QThread::msleep(300);  // a few more parts
    ASSERT_EQ(process.state(), QProcess::Running) << "the run ended before it could be interrupted";
    ASSERT_EQ(::kill(static_cast<pid_t>(process.processId()), SIGINT), 0);
    ASSERT_TRUE(process.waitForFinished(tt::test::kPatientWaitMs));
    err += process.readAllStandardError();
    EXPECT_EQ(process.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(process.exitCode(), 130) << err.constData();
    EXPECT_TRUE(err.contains("every finished part is stored; continue with: trueturn simulate --db"))
        << err.constData();
    EXPECT_TRUE(process.readAllStandardOutput().isEmpty());

    // Consistent and resumable: the run is still "running", its parts 1..n stored once each.
    EXPECT_EQ(sql(db, QStringLiteral("SELECT status FROM runs")), QStringLiteral("running"));
    const int stored = sql(db, QStringLiteral("SELECT COUNT(*) FROM parts")).toInt();
    EXPECT_GT(stored, 0);
    EXPECT_LT(stored, parts);
    EXPECT_EQ(sql(db, QStringLiteral("SELECT MAX(part_number) FROM parts")).toInt(), stored);
    EXPECT_EQ(sql(db, QStringLiteral("PRAGMA integrity_check")), QStringLiteral("ok"));

    const CliResult resumed = runTrueturn({QStringLiteral("simulate"), QStringLiteral("--db"), db,
                                           QStringLiteral("--resume"), QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(resumed.exitCode, 0) << qPrintable(resumed.err);
    EXPECT_EQ(resumed.json().value(QStringLiteral("parts")).toInt(), parts);
    EXPECT_EQ(sql(db, QStringLiteral("SELECT COUNT(*), COUNT(DISTINCT part_number), MIN(part_number), "
                                     "MAX(part_number) FROM parts")),
              QStringLiteral("%1|%1|1|%1").arg(parts));
    EXPECT_EQ(sql(db, QStringLiteral("SELECT status FROM runs")), QStringLiteral("complete"));
}

TEST_F(RunControl, CtrlCStopsCornerTrainingWithProgressAndWritesNothing) {
    // 2000 training moves take about a minute; the progress on stderr says where it is.
    const QString net = path(QStringLiteral("net.json"));
    QProcess process;
    process.start(QStringLiteral(TRUETURN_EXE),
                  {QStringLiteral("corner"), QStringLiteral("train"), QStringLiteral("--moves"), QStringLiteral("2000"),
                   QStringLiteral("--progress"), QStringLiteral("--out"), net});
    ASSERT_TRUE(process.waitForStarted());
    QElapsedTimer timer;
    timer.start();
    QByteArray err;
    while (!err.contains("targets: 2") && timer.elapsed() < 60000 && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        err += process.readAllStandardError();
    }
    ASSERT_EQ(process.state(), QProcess::Running) << "the training ended before it could be interrupted";
    EXPECT_TRUE(err.contains(" of 2000 (")) << err.constData();
    ASSERT_EQ(::kill(static_cast<pid_t>(process.processId()), SIGINT), 0);
    ASSERT_TRUE(process.waitForFinished(tt::test::kPatientWaitMs));
    err += process.readAllStandardError();
    EXPECT_EQ(process.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(process.exitCode(), 130) << err.constData();
    EXPECT_TRUE(err.contains("trueturn corner train: interrupted; no network was written")) << err.constData();
    EXPECT_FALSE(QFile::exists(net));
}

}  // namespace
