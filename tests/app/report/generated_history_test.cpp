// `trueturn generate-history` (the big histories of docs/BENCHMARKS.md) and `trueturn report` over what it
// writes: every generated reading counted once, the report's n and verdicts equal the stored readings of the
// point, and bad input refused with the reason.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QSqlQuery>

#include "cli_test.h"
#include "core/storage/database.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

class GeneratedHistoryTest : public test::CliTest {};

qint64 scalar(const QString& db, const QString& sql) {
    storage::Database history(storage::DatabaseConfig::sqlite(db));
    QSqlQuery q = history.exec(sql);
    return q.next() ? q.value(0).toLongLong() : -1;
}

TEST_F(GeneratedHistoryTest, ReportCountsEveryGeneratedReadingOfThePoint) {
    const QString db = path("big.sqlite");
    const CliResult g =
        runTrueturn({"generate-history", "--db", db, "--parts", "3000", "--runs", "3", "--machines", "2", "--json"});
    ASSERT_EQ(g.exitCode, 0) << qPrintable(g.err);
    EXPECT_EQ(g.json()["parts"].toInteger(), 3000);
    EXPECT_EQ(g.json()["readings"].toInteger(), 15000);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM parts")), 3000);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements")), 15000);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(DISTINCT machine) FROM runs")), 2);

    const CliResult r = runTrueturn({"report", "--db", db, "--point", "2", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject p = r.json()["points"].toArray().at(0).toObject();
    // The refused readings (reason_kind 'implausible', about 0.1 %) are not counted; every other one has a verdict.
    const qint64 plausible = scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements WHERE point_index = 1"
                                                       " AND reason_kind IS NULL"));
    EXPECT_EQ(p["n"].toInteger(), plausible);
    EXPECT_LT(plausible, 3000);
    const QJsonObject v = p["verdicts"].toObject();
    EXPECT_EQ(v["good"].toInteger() + v["rework"].toInteger() + v["scrap"].toInteger(), plausible);
    EXPECT_EQ(v["scrap"].toInteger(), scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements WHERE"
                                                                " point_index = 1 AND verdict = 'scrap'")));
    EXPECT_DOUBLE_EQ(p["x_mm"].toDouble(), 42.5);  // 10 + 130 * 1 / 4 mm (synthetic_history.cpp)
}

TEST_F(GeneratedHistoryTest, BadInputIsRefusedWithTheReason) {
    test::expectRefused({"generate-history", "--db", path("x.sqlite"), "--parts", "0"}, "--parts");
    test::expectRefused({"generate-history", "--db", path("x.sqlite"), "--parts", "5", "--runs", "6"}, "--runs");
    test::expectRefused({"generate-history", "--db", path("x.sqlite"), "--points", "17"}, "--points");
    test::expectRefused({"generate-history", "--parts", "10"}, "--db");
}

}  // namespace
}  // namespace tt
