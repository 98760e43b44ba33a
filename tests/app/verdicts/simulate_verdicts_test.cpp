// `trueturn simulate` with the tolerance of the job (issue 12): a tolerance tighter than the scatter of the
// parts gives rework and scrap counts in the JSON, out-of-tolerance alarms and a verdict stored with every
// plausible reading, apart from "accepted".
#include <gtest/gtest.h>

#include <QJsonObject>
#include <QSqlQuery>

#include "cli_test.h"
#include "core/storage/database.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

class SimulateVerdicts : public test::CliTest {};

qint64 scalar(storage::Database& db, const QString& sql) {
    QSqlQuery q = db.exec(sql);
    return q.next() ? q.value(0).toLongLong() : -1;
}

// The physical lathe of paper-2012-group1 scatters about 0.02-0.03 mm on diameter (sigma; var_closed about
// 5e-4 mm^2 under LQG); h6 on 27 mm is 0 / -0.013 mm (ISO 286-1), far tighter: most parts are out of it
// on one side or the other.
TEST_F(SimulateVerdicts, ATightToleranceGivesReworkScrapAlarmsAndStoredVerdicts) {
    const QString preset =
        write("tight.json", R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"fit": "h6"}}})");
    const QString db = path("history.sqlite");
    const CliResult r = runTrueturn(
        {"simulate", "--preset", preset, "--parts", "150", "--warmup", "0", "--seed", "5", "--db", db, "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject verdicts = r.json()["verdicts"].toObject();
    const qint64 good = verdicts["good"].toInteger(), rework = verdicts["rework"].toInteger(),
                 scrap = verdicts["scrap"].toInteger();
    EXPECT_GT(rework, 0);
    EXPECT_GT(scrap, 0);
    EXPECT_EQ(good + rework + scrap, 150) << "every measured part is judged";

    storage::Database history(storage::DatabaseConfig::sqlite(db));
    // The part's verdict is the worst of its points: counted from the stored readings.
    const auto partsWith = [&](const char* verdict, const char* worse) {
        return scalar(history,
                      QStringLiteral("SELECT COUNT(DISTINCT part_id) FROM measurements WHERE verdict = '%1'"
                                     " AND part_id NOT IN (SELECT part_id FROM measurements WHERE verdict IN (%2))")
                          .arg(QLatin1String(verdict), QLatin1String(worse)));
    };
    EXPECT_EQ(partsWith("scrap", "''"), scrap);
    EXPECT_EQ(partsWith("rework", "'scrap'"), rework);
    // One alarm per point out of tolerance; the stored limits are those of h6.
    EXPECT_EQ(scalar(history, "SELECT COUNT(*) FROM alarms WHERE kind = 'out-of-tolerance'"),
              r.json()["tolerance_alarms"].toInteger());
    EXPECT_EQ(scalar(history, "SELECT COUNT(*) FROM measurements WHERE verdict <> 'good'"),
              r.json()["tolerance_alarms"].toInteger());
    EXPECT_EQ(scalar(history,
                     "SELECT COUNT(*) FROM measurements WHERE verdict IS NOT NULL AND"
                     " (ABS(upper_limit_mm - 27.0) > 1e-9 OR ABS(lower_limit_mm - 26.987) > 1e-9)"),
              0);
    // Verdicts are kept apart from "accepted": scrap readings the controller still used.
    EXPECT_GT(scalar(history, "SELECT COUNT(*) FROM measurements WHERE verdict = 'scrap' AND accepted = 1"), 0);
    // The verdict agrees with the stored reading and limits.
    EXPECT_EQ(
        scalar(history, "SELECT COUNT(*) FROM measurements WHERE verdict = 'scrap' AND measured_mm >= lower_limit_mm"),
        0);
    EXPECT_EQ(
        scalar(history, "SELECT COUNT(*) FROM measurements WHERE verdict = 'rework' AND measured_mm <= upper_limit_mm"),
        0);
}

TEST_F(SimulateVerdicts, ABadToleranceIsRefusedNamingTheField) {
    const QString hole =
        write("hole.json", R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"fit": "H7"}}})");
    test::expectRefused({"simulate", "--preset", hole, "--parts", "100"}, "loop.tolerance");
    const QString inverted =
        write("inverted.json",
              R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"upper_mm": -0.05, "lower_mm": 0.01}}})");
    test::expectRefused({"simulate", "--preset", inverted, "--parts", "100"}, "lower deviation");
}

}  // namespace
}  // namespace tt
