// Reports from a PostgreSQL hot standby: the quality engineer's reports read a streaming replica
// (scripts/start-test-postgres.sh --standby), in read-only transactions, and give the primary's figures; the
// report's connection can change nothing, even on the primary; the plant overview reads the standby too.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QJsonArray>
#include <QSqlQuery>
#include <QThread>

#include "../cli_runner.h"
#include "core/storage/database.h"
#include "tests/support/own_postgres.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

qint64 parts(const QString& url) {
    try {
        storage::DatabaseConfig c = storage::DatabaseConfig::postgresUrl(url);
        c.readOnly = true;
        storage::Database db(c);
        if (!db.hasTable(QStringLiteral("parts"))) return -1;
        QSqlQuery q = db.exec(QStringLiteral("SELECT COUNT(*) FROM parts"));
        return q.next() ? q.value(0).toLongLong() : -1;
    } catch (const storage::StorageError&) {
        return -1;
    }
}

TEST(StandbyReport, TheReportOfAHotStandbyIsThePrimarysAndChangesNothing) {
    test::OwnPostgres primary;
    if (!primary.ok()) {
        if (TRUETURN_POSTGRES_REQUIRED) FAIL() << "no PostgreSQL server: " << primary.problem().toStdString();
        GTEST_SKIP() << "needs the PostgreSQL server binaries: " << primary.problem().toStdString();
    }
    test::OwnPostgres standby(&primary);
    ASSERT_TRUE(standby.ok()) << standby.problem().toStdString();
    const QString writer = primary.url(QStringLiteral("trueturn"), QStringLiteral("postgres"));
    const QString replica = standby.url(QStringLiteral("quality"), QStringLiteral("postgres"));
    const CliResult generated = runTrueturn({"generate-history", "--db", writer, "--parts", "1500", "--machines", "2"});
    ASSERT_EQ(generated.exitCode, 0) << qPrintable(generated.err);
    // The standby replays the primary's WAL within moments.
    QElapsedTimer waited;
    waited.start();
    while (parts(replica) != 1500 && waited.elapsed() < 60000)
        QThread::msleep(100);
    ASSERT_EQ(parts(replica), 1500);

    const QStringList report{"report", "--point", "2", "--json"};
    const CliResult onPrimary = runTrueturn(QStringList{"report", "--db", writer} + report.mid(1));
    const CliResult onStandby = runTrueturn(QStringList{"report", "--db", replica} + report.mid(1));
    ASSERT_EQ(onPrimary.exitCode, 0) << qPrintable(onPrimary.err);
    ASSERT_EQ(onStandby.exitCode, 0) << qPrintable(onStandby.err);
    EXPECT_EQ(onStandby.json(), onPrimary.json());
    EXPECT_EQ(onStandby.json()["points"].toArray()[0].toObject()["point"].toInt(), 2);
    const CliResult plant = runTrueturn({"plant", "--db", replica, "--json"});
    ASSERT_EQ(plant.exitCode, 0) << qPrintable(plant.err);
    EXPECT_EQ(plant.json()["machines"].toArray().size(), 2);

    // A report's connection is read-only: a write is refused by the server, on the primary as well.
    storage::DatabaseConfig readOnly = storage::DatabaseConfig::postgresUrl(writer);
    readOnly.readOnly = true;
    storage::Database db(readOnly);
    try {
        db.exec(QStringLiteral("DELETE FROM measurements"));
        FAIL() << "a read-only connection deleted readings";
    } catch (const storage::StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("read-only transaction"), std::string::npos) << e.what();
    }
    EXPECT_EQ(parts(writer), 1500);
}

}  // namespace
}  // namespace tt
