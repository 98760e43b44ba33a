// The plant-wide history under a failing server: four terminals (`trueturn simulate --db postgresql://... --machine
// mN --parts 2000`, each with its own journal and its own login) write at full speed while the PostgreSQL server is
// stopped at once (pg_ctl stop -m immediate) and started again five times at random moments. Every process exits 0,
// and the plant database holds exactly 4 x 2000 parts x 5 points, each once, equal to what each terminal's journal
// holds. The same with one terminal killed (SIGKILL) mid-run and continued with --resume.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <chrono>
#include <memory>
#include <random>
#include <vector>

#include "tests/core/storage/journal_support.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "tests/support/own_postgres.h"

namespace tt {
namespace {

constexpr int kTerminals = 4;
constexpr int kParts = 2000;
constexpr int kRestarts = 5;

qint64 scalar(storage::Database& db, const QString& sql, const QVariantList& bindings = {}) {
    QSqlQuery q = db.exec(sql, bindings);
    return q.next() ? q.value(0).toLongLong() : -1;
}

class PlantChaos : public ::testing::Test {
protected:
    void SetUp() override {
        server = std::make_unique<test::OwnPostgres>();
        if (!server->ok()) {
            if (TRUETURN_POSTGRES_REQUIRED) FAIL() << "no PostgreSQL server: " << server->problem().toStdString();
            GTEST_SKIP() << "needs the PostgreSQL server binaries: " << server->problem().toStdString();
        }
        storage::Database admin(storage::DatabaseConfig::postgresUrl(server->url("trueturn", "postgres")));
        admin.exec(QStringLiteral("CREATE DATABASE plant"));
        // The plant's owner brings the schema up (tables, roles, policies) and lets each login write its machine.
        storage::Database owner(ownerConfig());
        owner.migrate(storage::historySchema());
        for (int i = 1; i <= kTerminals; ++i)
            owner.exec(QStringLiteral("INSERT INTO plant_terminals (login, machine) VALUES ('terminal_m%1', 'm%1')").arg(i));
        const unsigned seed = std::random_device{}();
        random.seed(seed);
        RecordProperty("seed", static_cast<int>(seed));
        std::printf("chaos seed %u\n", seed);
    }

    storage::DatabaseConfig ownerConfig() const {
        return storage::DatabaseConfig::postgresUrl(server->url("trueturn", "plant"));
    }
    QString journal(int i) const { return dir.filePath(QStringLiteral("m%1.sqlite").arg(i)); }
    QString log(int i, bool resume, const char* stream) const {
        return dir.filePath(QStringLiteral("m%1%2.%3").arg(i).arg(resume ? "-resumed" : "").arg(QLatin1String(stream)));
    }
    QString logText(int i, bool resume, const char* stream) const {
        QFile f(log(i, resume, stream));
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }

    std::unique_ptr<QProcess> terminal(int i, bool resume) {
        auto p = std::make_unique<QProcess>();
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
        p->setProcessEnvironment(env);
        // Output into files: the test sleeps between its checks and never fills a pipe the terminal waits on.
        p->setStandardOutputFile(log(i, resume, "out"));
        p->setStandardErrorFile(log(i, resume, "err"));
        QStringList args{"simulate",      "--db",      server->url(QStringLiteral("terminal_m%1").arg(i), "plant"),
                         "--machine",     QStringLiteral("m%1").arg(i),
                         "--journal",     journal(i),
                         "--drain-wait",  "600",
                         "--progress",    "--json"};
        if (resume)
            args << "--resume";
        else
            args << "--preset" << "paper-2012" << "--parts" << QString::number(kParts) << "--warmup" << "0" << "--seed"
                 << QString::number(i);
        p->start(QStringLiteral(TRUETURN_EXE), args);
        return p;
    }

    /// The newest part a terminal's journal holds (0 before its first).
    qint64 journalParts(int i) const {
        if (!QFile::exists(journal(i))) return 0;
        try {
            storage::DatabaseConfig c = storage::DatabaseConfig::sqlite(journal(i));
            c.readOnly = true;
            storage::Database j(c);
            return scalar(j, QStringLiteral("SELECT COALESCE(MAX(part_number), 0) FROM parts"));
        } catch (const storage::StorageError&) {
            return 0;
        }
    }

    static bool anyRunning(const std::vector<std::unique_ptr<QProcess>>& terminals) {
        for (const auto& p : terminals)
            if (p->state() != QProcess::NotRunning) return true;
        return false;
    }

    /// Sleeps `seconds` while serving the processes' output pipes.
    static void pause(double seconds) { QThread::msleep(static_cast<unsigned long>(seconds * 1000.0)); }

    /// Stops the server at once and starts it again, kRestarts times at random moments; returns how many of the
    /// stops came while a terminal was still running.
    int crashAndRestart(const std::vector<std::unique_ptr<QProcess>>& terminals) {
        std::uniform_real_distribution<double> up(0.2, 1.5), down(0.3, 2.5);
        int duringRun = 0;
        for (int k = 0; k < kRestarts; ++k) {
            pause(up(random));
            duringRun += anyRunning(terminals) ? 1 : 0;
            EXPECT_TRUE(server->crash()) << server->problem().toStdString();
            pause(down(random));
            EXPECT_TRUE(server->restart()) << server->problem().toStdString();
        }
        return duringRun;
    }

    void finishAll(std::vector<std::unique_ptr<QProcess>>& terminals, int resumed = 0) {
        for (std::size_t i = 0; i < terminals.size(); ++i) {
            QProcess& p = *terminals[i];
            const int n = static_cast<int>(i) + 1;
            ASSERT_TRUE(p.waitForFinished(900000)) << "terminal " << n << " did not end";
            const QString err = logText(n, n == resumed, "err");
            EXPECT_EQ(p.exitStatus(), QProcess::NormalExit);
            EXPECT_EQ(p.exitCode(), 0) << "terminal " << n << ": " << err.toStdString();
            const QJsonObject out = QJsonDocument::fromJson(logText(n, n == resumed, "out").toUtf8()).object();
            EXPECT_TRUE(out[QStringLiteral("plant")].toObject()[QStringLiteral("drained")].toBool())
                << "terminal " << n << ": " << err.toStdString();
        }
    }

    /// The plant database holds each terminal's 2000 parts x 5 points once, equal to its journal.
    void expectEveryPartOnce() {
        storage::Database plant(ownerConfig());
        storage::SqlHistoryStore plantHistory(plant);
        EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COUNT(*) FROM parts")), kTerminals * kParts);
        EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COUNT(*) FROM measurements")), kTerminals * kParts * 5);
        EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COUNT(*) FROM corrections")), kTerminals * kParts * 5);
        for (int i = 1; i <= kTerminals; ++i) {
            SCOPED_TRACE("terminal m" + std::to_string(i));
            const QString machine = QStringLiteral("m%1").arg(i);
            EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COUNT(*) FROM runs WHERE machine = ?"), {machine}), 1);
            EXPECT_EQ(scalar(plant,
                             QStringLiteral("SELECT COUNT(DISTINCT p.part_number) FROM parts p JOIN runs r ON r.id ="
                                            " p.run_id WHERE r.machine = ? AND p.part_number BETWEEN 1 AND ?"),
                             {machine, kParts}),
                      kParts);
            storage::DatabaseConfig c = storage::DatabaseConfig::sqlite(journal(i));
            c.readOnly = true;
            storage::Database journalDb(c);
            storage::SqlHistoryStore journalHistory(journalDb);
            const std::vector<core::RunSummary> runs = journalHistory.runs();
            ASSERT_EQ(runs.size(), 1u);
            EXPECT_EQ(runs.front().status, "complete");
            const std::optional<std::int64_t> plantRun =
                storage::test::runByUid(plant, storage::test::uidOf(journalDb, runs.front().runId));
            ASSERT_TRUE(plantRun);
            storage::test::expectSameRun(journalHistory, runs.front().runId, plantHistory, *plantRun);
        }
        // Nothing left on the terminals: each reported an empty backlog.
        EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COALESCE(SUM(backlog_parts), -1) FROM plant_terminal_status")), 0);
    }

    std::unique_ptr<test::OwnPostgres> server;
    QTemporaryDir dir;
    std::mt19937 random;
};

TEST_F(PlantChaos, FourTerminalsKeepEveryPartWhileTheServerIsStoppedAndStartedFiveTimes) {
    std::vector<std::unique_ptr<QProcess>> terminals;
    for (int i = 1; i <= kTerminals; ++i)
        terminals.push_back(terminal(i, false));
    QElapsedTimer started;
    started.start();
    while (journalParts(1) < 20 && started.elapsed() < 60000 && anyRunning(terminals))
        pause(0.05);
    const int duringRun = crashAndRestart(terminals);
    RecordProperty("stops_while_running", duringRun);
    finishAll(terminals);
    expectEveryPartOnce();
}

TEST_F(PlantChaos, ATerminalKilledMidRunContinuesWithResumeAndSendsWhatItHadNotSent) {
    std::vector<std::unique_ptr<QProcess>> terminals;
    for (int i = 1; i <= kTerminals; ++i)
        terminals.push_back(terminal(i, false));
    // Killed (SIGKILL) at a random part between 200 and 1500, the server stopped meanwhile too.
    const qint64 killAt = std::uniform_int_distribution<qint64>(200, 1500)(random);
    QElapsedTimer started;
    started.start();
    while (journalParts(1) < killAt / 2 && started.elapsed() < 300000 && terminals[0]->state() != QProcess::NotRunning)
        pause(0.02);
    ASSERT_TRUE(server->crash());
    while (journalParts(1) < killAt && started.elapsed() < 300000 && terminals[0]->state() != QProcess::NotRunning)
        pause(0.02);
    ASSERT_NE(terminals[0]->state(), QProcess::NotRunning) << "terminal 1 ended before part " << killAt;
    terminals[0]->kill();
    ASSERT_TRUE(terminals[0]->waitForFinished(10000));
    EXPECT_EQ(terminals[0]->exitStatus(), QProcess::CrashExit);
    const qint64 keptAtKill = journalParts(1);
    RecordProperty("killed_after_part", static_cast<int>(keptAtKill));
    pause(1.0);
    ASSERT_TRUE(server->restart());
    terminals[0] = terminal(1, true);
    crashAndRestart(terminals);
    finishAll(terminals, 1);
    expectEveryPartOnce();
}

}  // namespace
}  // namespace tt
