// `trueturn plant --json` on SQLite and PostgreSQL: every machine with its state, last part, its terminal's backlog,
// the day's verdicts and its open alarms; the figures are the report's: per point the Cpk of the last 125 parts and
// of the 125 before are recomputed by `trueturn report --machine M --point I --last 125 [--skip 125]`, the day's
// verdicts by `trueturn report --machine M --from DAY --to DAY` (part_verdicts).
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QSqlQuery>

#include "tests/core/storage/scratch_database.h"
#include "../cli_runner.h"
#include "core/storage/history_store.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

/// Every process in UTC: the plant's "today" is the local day.
QProcessEnvironment utc() {
    QProcessEnvironment env;
    env.insert(QStringLiteral("TZ"), QStringLiteral("UTC"));
    return env;
}

QString urlOf(const storage::DatabaseConfig& c) {
    if (c.kind == storage::DatabaseConfig::Kind::Sqlite) return c.sqlitePath;
    return QStringLiteral("postgresql://%1@%2:%3/%4").arg(c.user, c.host).arg(c.port).arg(c.databaseName);
}

class PlantCommand : public ::testing::TestWithParam<std::string> {};

TEST_P(PlantCommand, ShowsEveryMachineWithTheReportsFigures) {
    storage::test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    const QString db = urlOf(scratch.config());
    // Three lathes side by side from 2026-03-09 12:00 UTC, one part a minute, 1000 parts each (two runs of 500):
    // the last part of each at 2026-03-10 04:39, 280 parts on 2026-03-10.
    const CliResult generated = runTrueturn({"generate-history", "--db", db, "--parts", "3000", "--machines", "3",
                                             "--runs", "6", "--parallel", "--start", "2026-03-09T12:00:00Z"});
    ASSERT_EQ(generated.exitCode, 0) << qPrintable(generated.err);
    {
        // lathe-1's terminal last reported 5 minutes before the overview (offline), with 42 parts kept; lathe-4 is
        // running a run with an open alarm.
        storage::Database owner(scratch.config());
        owner.exec(QStringLiteral("INSERT INTO plant_terminal_status (machine, reported_at, backlog_parts, journal_bytes,"
                                  " journal_limit_bytes) VALUES ('lathe-1', '2026-03-10T09:55:00.000Z', 42, 1000, 1073741824)"));
        storage::SqlHistoryStore history(owner);
        core::RunDescription run{"paper-2012", "lqg", 1, 27.0, 325.0, {0.0, 100.0}, "{}", "lathe-4"};
        const std::int64_t id = history.beginRun(run);
        history.recordAlarm(id, {std::nullopt, 1.0, "gauge-silent", "the gauge is not ready"});
    }
    const CliResult plant = runTrueturn({"plant", "--db", db, "--at", "2026-03-10T10:00:00Z", "--json"}, 120000, utc());
    ASSERT_EQ(plant.exitCode, 0) << qPrintable(plant.err);
    const QJsonObject out = plant.json();
    EXPECT_EQ(out["day_from"].toString(), QStringLiteral("2026-03-10T00:00:00.000Z"));
    EXPECT_EQ(out["window_parts"].toInt(), 125);
    const QJsonArray machines = out["machines"].toArray();
    ASSERT_EQ(machines.size(), 4);
    for (int k = 0; k < 3; ++k) {
        const QJsonObject m = machines[k].toObject();
        const QString name = m["machine"].toString();
        SCOPED_TRACE(name.toStdString());
        EXPECT_EQ(name, QStringLiteral("lathe-%1").arg(k + 1));
        EXPECT_EQ(m["state"].toString(), k == 0 ? QStringLiteral("offline") : QStringLiteral("idle"));
        EXPECT_EQ(m["last_part_at"].toString(), QStringLiteral("2026-03-10T04:39:00.000Z"));
        EXPECT_EQ(m["backlog_parts"].isNull(), k != 0);
        if (k == 0) {
            EXPECT_EQ(m["backlog_parts"].toInteger(), 42);
        }
        EXPECT_EQ(m["open_alarms"].toInteger(), 0);
        // The day's parts, as the report counts them.
        const QJsonObject today = m["today"].toObject();
        EXPECT_EQ(today["parts"].toInteger(), 280);
        const CliResult day = runTrueturn({"report", "--db", db, "--machine", name, "--from", out["day_from"].toString(),
                                           "--to", out["day_to"].toString(), "--json"});
        ASSERT_EQ(day.exitCode, 0) << qPrintable(day.err);
        const QJsonObject verdicts = day.json()["part_verdicts"].toObject();
        for (const char* v : {"good", "rework", "scrap"})
            EXPECT_EQ(today[QLatin1String(v)].toInteger(), verdicts[QLatin1String(v)].toInteger()) << v;
        EXPECT_GT(today["good"].toInteger(), 0);
        // Per point: Cpk of the last 125 parts and of the 125 before, recomputed by the report.
        const QJsonArray points = m["points"].toArray();
        ASSERT_EQ(points.size(), 5);
        for (const QJsonValue& pv : points) {
            const QJsonObject p = pv.toObject();
            const QString point = QString::number(p["point"].toInt());
            SCOPED_TRACE("point " + point.toStdString());
            EXPECT_EQ(p["n"].toInteger(), 125);
            EXPECT_EQ(p["n_before"].toInteger(), 125);
            const CliResult last = runTrueturn(
                {"report", "--db", db, "--machine", name, "--point", point, "--last", "125", "--json"});
            const CliResult before = runTrueturn({"report", "--db", db, "--machine", name, "--point", point, "--last",
                                                  "125", "--skip", "125", "--json"});
            ASSERT_EQ(last.exitCode, 0) << qPrintable(last.err);
            ASSERT_EQ(before.exitCode, 0) << qPrintable(before.err);
            const QJsonObject r1 = last.json()["points"].toArray()[0].toObject();
            const QJsonObject r2 = before.json()["points"].toArray()[0].toObject();
            EXPECT_EQ(r1["n"].toInteger(), 125);
            ASSERT_TRUE(p["cpk"].isDouble());
            EXPECT_DOUBLE_EQ(p["cpk"].toDouble(), r1["cpk"].toDouble());
            EXPECT_DOUBLE_EQ(p["cpk_before"].toDouble(), r2["cpk"].toDouble());
            EXPECT_DOUBLE_EQ(p["cpk_change"].toDouble(), r1["cpk"].toDouble() - r2["cpk"].toDouble());
        }
    }
    const QJsonObject running = machines[3].toObject();
    EXPECT_EQ(running["machine"].toString(), QStringLiteral("lathe-4"));
    EXPECT_EQ(running["open_alarms"].toInteger(), 1);
    EXPECT_EQ(running["alarms"].toArray()[0].toObject()["kind"].toString(), QStringLiteral("gauge-silent"));
    EXPECT_TRUE(running["last_part_at"].isNull());
}

TEST_P(PlantCommand, RefusesBadInputWithAReason) {
    storage::test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    const CliResult missing = runTrueturn({"plant", "--json"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains(QLatin1String("--db"))) << qPrintable(missing.err);
    const CliResult at = runTrueturn({"plant", "--db", urlOf(scratch.config()), "--at", "yesterday"});
    EXPECT_EQ(at.exitCode, 2);
    EXPECT_TRUE(at.err.contains(QLatin1String("--at"))) << qPrintable(at.err);
}

INSTANTIATE_TEST_SUITE_P(Backends, PlantCommand, ::testing::ValuesIn(storage::test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt
