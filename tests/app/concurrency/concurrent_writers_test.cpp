// A plant-wide history (issue 12): four `trueturn simulate --db` processes write one database at the same
// moment, on SQLite (writers wait on the busy file instead of failing with "database is locked") and on
// PostgreSQL (the schema is created under an advisory lock); every part of every run is stored exactly once.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <memory>
#include <vector>

#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "tests/core/storage/scratch_database.h"
#include "tests/support/patient_wait.h"

namespace tt {
namespace {

constexpr int kWriters = 4;
constexpr int kParts = 100;  // the fewest `simulate` counts

qint64 scalar(storage::Database& db, const QString& sql, const QVariantList& bindings = {}) {
    QSqlQuery q = db.exec(sql, bindings);
    return q.next() ? q.value(0).toLongLong() : -1;
}

/// Starts the writers together, waits for all, and checks each run in the database `config` names.
void runWriters(const QString& dbOption, const storage::DatabaseConfig& config) {
    std::vector<std::unique_ptr<QProcess>> writers;
    for (int i = 0; i < kWriters; ++i) {
        auto p = std::make_unique<QProcess>();
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        p->setProcessEnvironment(env);
        // The statistical plant (preset paper-2012): fast parts, many transactions close together.
        p->start(QStringLiteral(TRUETURN_EXE),
                 {"simulate", "--preset", "paper-2012", "--parts", QString::number(kParts), "--warmup", "0", "--seed",
                  QString::number(i + 1), "--db", dbOption, "--json"});
        writers.push_back(std::move(p));
    }
    for (auto& p : writers)
        p->waitForFinished(tt::test::kPatientWaitMs);
    for (auto& p : writers) {
        ASSERT_EQ(p->state(), QProcess::NotRunning);
        const QString err = QString::fromUtf8(p->readAllStandardError());
        ASSERT_EQ(p->exitCode(), 0) << qPrintable(err);
        EXPECT_FALSE(err.contains(QLatin1String("locked"))) << qPrintable(err);
    }
    storage::Database db(config);
    // The runs as the database numbered them: a plant database (postgresql://) gets them through each terminal's
    // journal, whose own run numbers (the JSON's run_id) are not the plant's.
    std::vector<qint64> runIds;
    for (QSqlQuery q = db.exec(QStringLiteral("SELECT id FROM runs ORDER BY id")); q.next();)
        runIds.push_back(q.value(0).toLongLong());
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM runs")), kWriters);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM schema_versions WHERE module = 'history'")),
              static_cast<qint64>(storage::historySchema().migrations.size()))
        << "each migration applied once";
    for (const qint64 run : runIds) {
        SCOPED_TRACE(run);
        EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM parts WHERE run_id = ?"), {run}), kParts);
        EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(DISTINCT part_number) FROM parts WHERE run_id = ?"), {run}),
                  kParts);
        EXPECT_EQ(scalar(db, QStringLiteral("SELECT MIN(part_number) FROM parts WHERE run_id = ?"), {run}), 1);
        EXPECT_EQ(scalar(db, QStringLiteral("SELECT MAX(part_number) FROM parts WHERE run_id = ?"), {run}), kParts);
        EXPECT_EQ(scalar(db,
                         QStringLiteral("SELECT COUNT(*) FROM measurements m JOIN parts p ON p.id = m.part_id"
                                        " WHERE p.run_id = ?"),
                         {run}),
                  kParts * 5)
            << "every part measured at its five points, once";
        // The run's end: its status on SQLite, a row of run_ends on a plant database (its roles never update).
        EXPECT_EQ(scalar(db,
                         QStringLiteral(
                             "SELECT COUNT(*) FROM runs r WHERE r.id = ? AND (r.status = 'complete' OR"
                             " EXISTS (SELECT 1 FROM run_ends e WHERE e.run_id = r.id AND e.status = 'complete'))"),
                         {run}),
                  1);
    }
}

TEST(ConcurrentWriters, FourSimulationsWriteOneSqliteFile) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("plant.sqlite"));
    runWriters(file, storage::DatabaseConfig::sqlite(file));
}

TEST(ConcurrentWriters, FourSimulationsWriteOnePostgresDatabase) {
    storage::test::ScratchDatabase scratch("postgres");
    TT_REQUIRE_BACKEND(scratch);
    const storage::DatabaseConfig& c = scratch.config();
    const QString url = QStringLiteral("postgresql://%1@%2:%3/%4").arg(c.user, c.host).arg(c.port).arg(c.databaseName);
    runWriters(url, c);
}

}  // namespace
}  // namespace tt
