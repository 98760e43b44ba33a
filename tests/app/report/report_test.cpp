// `trueturn report` on a history written by `trueturn simulate` (issue 12): the JSON per control point with
// the issue's fields, its figures recomputed here from the stored readings by the textbook formulas, the
// verdict counts as stored, and the CSV of every reading.
#include <gtest/gtest.h>

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSqlQuery>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "cli_test.h"
#include "core/storage/database.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

class ReportTest : public test::CliTest {
protected:
    /// A stored run of 150 parts of paper-2012-group1 judged against h7 (27 mm: 0 / -0.021 mm, ISO 286-1),
    /// tighter than the scatter: every verdict occurs.
    QString history() {
        const QString preset =
            write("h7.json", R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"fit": "h7"}}})");
        const QString db = path("history.sqlite");
        const CliResult r = runTrueturn(
            {"simulate", "--preset", preset, "--parts", "150", "--warmup", "0", "--seed", "11", "--db", db, "--json"});
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return db;
    }

    /// The plausible readings of point `point` (1-based), in part order, straight from the history.
    std::vector<double> readings(const QString& db, int point) {
        storage::Database history(storage::DatabaseConfig::sqlite(db));
        QSqlQuery q = history.exec(
            QStringLiteral("SELECT m.measured_mm FROM measurements m JOIN parts p ON p.id = m.part_id"
                           " WHERE m.point_index = ? AND m.measured_mm IS NOT NULL AND (m.reason_kind IS NULL OR"
                           " m.reason_kind <> 'implausible') ORDER BY p.part_number"),
            {point - 1});
        std::vector<double> values;
        while (q.next())
            values.push_back(q.value(0).toDouble());
        return values;
    }

    qint64 storedVerdicts(const QString& db, int point, const char* verdict) {
        storage::Database history(storage::DatabaseConfig::sqlite(db));
        QSqlQuery q =
            history.exec(QStringLiteral("SELECT COUNT(*) FROM measurements WHERE point_index = ? AND verdict = ?"),
                         {point - 1, QString::fromLatin1(verdict)});
        return q.next() ? q.value(0).toLongLong() : -1;
    }
};

double mean(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double sampleSigma(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0.0;
    for (double x : v)
        s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

TEST_F(ReportTest, JsonPerPointHasTheIssuesFieldsAndTheTextbookFigures) {
    const QString db = history();
    const CliResult r = runTrueturn({"report", "--db", db, "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonArray points = r.json()["points"].toArray();
    ASSERT_EQ(points.size(), 5);
    const QStringList keys{"cp",
                           "cpk",
                           "cpk_ci",
                           "cpm",
                           "limits",
                           "mean_mm",
                           "method",
                           "n",
                           "normality_p",
                           "point",
                           "pp",
                           "ppk",
                           "sigma_overall_mm",
                           "sigma_within_mm",
                           "verdicts",
                           "violation_count",
                           "violations",
                           "violations_by_rule",
                           "x_mm",
                           "controller_changes"};
    for (int i = 1; i <= 5; ++i) {
        const QJsonObject p = points[i - 1].toObject();
        QStringList have = p.keys();
        have.sort();
        QStringList want = keys;
        want.sort();
        EXPECT_EQ(have, want);
        EXPECT_EQ(p["point"].toInt(), i);
        const std::vector<double> x = readings(db, i);
        ASSERT_EQ(p["n"].toInteger(), static_cast<qint64>(x.size()));
        // I-MR (subgroup 1): sigma within = MR-bar / d2(2), d2(2) = 1.128 (Montgomery, Appendix VI; the
        // library's d2 is 1.12838, so 2e-4 relative); limits mean +- 3 sigma within. Doubles summed in another
        // order: 1e-9 mm.
        double mr = 0.0;
        for (std::size_t k = 1; k < x.size(); ++k)
            mr += std::fabs(x[k] - x[k - 1]);
        mr /= static_cast<double>(x.size() - 1);
        const double within = mr / 1.128;
        EXPECT_NEAR(p["mean_mm"].toDouble(), mean(x), 1e-9);
        EXPECT_NEAR(p["sigma_overall_mm"].toDouble(), sampleSigma(x), 1e-9);
        EXPECT_NEAR(p["sigma_within_mm"].toDouble() / within, 1.0, 2e-4);
        const QJsonObject limits = p["limits"].toObject();
        EXPECT_NEAR(limits["centre"].toDouble(), mean(x), 1e-9);
        EXPECT_NEAR(limits["ucl"].toDouble() - mean(x), 3.0 * within, 3.0 * within * 2e-4);
        EXPECT_NEAR(limits["r_centre"].toDouble(), mr, 1e-9);
        // Capability against h7 = 26.979 .. 27.000 mm: Cp = (U - L)/(6 sigma_w), Ppk = min(U - mean, mean -
        // L)/(3 sigma_o) (NIST/SEMATECH e-Handbook 6.1.6) when normality is not rejected.
        const double upper = 27.0, lower = 26.979;
        EXPECT_NEAR(p["cp"].toDouble(), (upper - lower) / (6.0 * p["sigma_within_mm"].toDouble()), 1e-9);
        if (p["method"].toString() == QLatin1String("normal")) {
            EXPECT_NEAR(p["ppk"].toDouble(), std::min(upper - mean(x), mean(x) - lower) / (3.0 * sampleSigma(x)), 1e-9);
            const QJsonArray ci = p["cpk_ci"].toArray();
            ASSERT_EQ(ci.size(), 2);
            EXPECT_LT(ci[0].toDouble(), p["cpk"].toDouble());
            EXPECT_GT(ci[1].toDouble(), p["cpk"].toDouble());
        }
        EXPECT_GT(p["normality_p"].toDouble(), 0.0);
        // Verdicts as stored with the readings.
        const QJsonObject verdicts = p["verdicts"].toObject();
        EXPECT_EQ(verdicts["good"].toInteger(), storedVerdicts(db, i, "good"));
        EXPECT_EQ(verdicts["rework"].toInteger(), storedVerdicts(db, i, "rework"));
        EXPECT_EQ(verdicts["scrap"].toInteger(), storedVerdicts(db, i, "scrap"));
        EXPECT_EQ(verdicts["good"].toInteger() + verdicts["rework"].toInteger() + verdicts["scrap"].toInteger(),
                  static_cast<qint64>(x.size()));
        for (const QJsonValue& v : p["violations"].toArray()) {
            EXPECT_TRUE(v.toObject()["rule"].toString().startsWith(QLatin1String("WE")));
            EXPECT_FALSE(v.toObject()["parts"].toArray().isEmpty());
        }
        // The counts by rule add up to every violation; at most the first 100 are listed by default.
        qint64 byRule = 0;
        for (const QJsonValue& n : p["violations_by_rule"].toObject())
            byRule += n.toInteger();
        EXPECT_EQ(byRule, p["violation_count"].toInteger());
        EXPECT_EQ(p["violations"].toArray().size(), std::min<qint64>(100, p["violation_count"].toInteger()));
    }
    // The list is as long as asked: --violations N or all.
    const QJsonObject all = runTrueturn({"report", "--db", db, "--point", "1", "--violations", "all", "--json"})
                                .json()["points"]
                                .toArray()[0]
                                .toObject();
    const QJsonObject one = runTrueturn({"report", "--db", db, "--point", "1", "--violations", "1", "--json"})
                                .json()["points"]
                                .toArray()[0]
                                .toObject();
    ASSERT_GT(all["violation_count"].toInteger(), 1);
    EXPECT_EQ(all["violations"].toArray().size(), all["violation_count"].toInteger());
    EXPECT_EQ(one["violations"].toArray().size(), 1);
    EXPECT_EQ(one["violations"].toArray()[0], all["violations"].toArray()[0]);
    EXPECT_EQ(runTrueturn({"report", "--db", db, "--violations", "some"}).exitCode, 2);
}

TEST_F(ReportTest, OnePointWithSubgroupsOfFiveAndTheCsvOfTheReadings) {
    const QString db = history();
    const QString csv = path("readings.csv");
    const CliResult r =
        runTrueturn({"report", "--db", db, "--run", "1", "--point", "3", "--subgroup", "5", "--json", "--csv", csv});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonArray points = r.json()["points"].toArray();
    ASSERT_EQ(points.size(), 1);
    const QJsonObject p = points[0].toObject();
    EXPECT_EQ(p["point"].toInt(), 3);
    EXPECT_DOUBLE_EQ(p["x_mm"].toDouble(), 162.5);
    // X-bar-R of consecutive subgroups of 5: R-bar is the mean range (150 readings: 30 subgroups).
    const std::vector<double> x = readings(db, 3);
    ASSERT_EQ(x.size(), 150u);
    double rbar = 0.0;
    for (std::size_t k = 0; k < 30; ++k) {
        const auto [lo, hi] = std::minmax_element(x.begin() + 5 * k, x.begin() + 5 * k + 5);
        rbar += *hi - *lo;
    }
    rbar /= 30.0;
    const QJsonObject limits = p["limits"].toObject();
    EXPECT_NEAR(limits["r_centre"].toDouble(), rbar, 1e-9);
    // D4(5) = 2.114, A2(5) = 0.577 (Montgomery, Appendix VI; three decimals: 1e-3 relative).
    EXPECT_NEAR(limits["r_ucl"].toDouble() / (2.114 * rbar), 1.0, 1e-3);
    EXPECT_NEAR((limits["ucl"].toDouble() - limits["centre"].toDouble()) / (0.577 * rbar), 1.0, 1e-3);

    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 151);
    EXPECT_EQ(lines[0], QStringLiteral("run,machine,part,time,point,x_mm,nominal_mm,measured_mm,deviation_mm,verdict"));
    const QStringList first = lines[1].split(QLatin1Char(','));
    ASSERT_EQ(first.size(), 10);
    EXPECT_EQ(first[0], QStringLiteral("1"));
    EXPECT_EQ(first[2], QStringLiteral("1"));
    EXPECT_TRUE(first[3].endsWith(QLatin1Char('Z')) && first[3].contains(QLatin1Char('T'))) << "ISO 8601 UTC";
    EXPECT_EQ(first[4], QStringLiteral("3"));
    EXPECT_NEAR(first[7].toDouble(), x[0], 5e-5);
    EXPECT_NEAR(first[8].toDouble(), first[7].toDouble() - first[6].toDouble(), 1e-9);
    const double measured = first[7].toDouble();
    const QString expected = measured > 27.0 ? "rework" : measured < 26.979 ? "scrap" : "good";
    EXPECT_EQ(first[9], expected);
}

// AQDEF (the Q-DAS transfer format): K0100 the number of characteristics; per characteristic K2001/K2002,
// K2022 decimal places, K2101 nominal, K2110/K2111 limits, K2142 unit; each value K0001/i with K0004/i date
// and time DD.MM.YYYY/HH:MM:SS; lines end in CR LF.
TEST_F(ReportTest, DfqForQdasHasTheCharacteristicsAndEveryValue) {
    const QString db = history();
    const QString dfq = path("run.dfq");
    const CliResult r = runTrueturn({"report", "--db", db, "--dfq", dfq});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    QFile file(dfq);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromLatin1(file.readAll());
    EXPECT_TRUE(text.endsWith(QLatin1String("\r\n")));
    const QStringList lines = text.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    ASSERT_FALSE(lines.isEmpty());
    EXPECT_EQ(lines[0], QStringLiteral("K0100 5"));
    const auto field = [&](const QString& key) {
        for (const QString& line : lines)
            if (line.startsWith(key + QLatin1Char(' '))) return line.mid(key.size() + 1);
        return QString();
    };
    EXPECT_EQ(field("K2001/3"), QStringLiteral("P3"));
    EXPECT_EQ(field("K2022/3"), QStringLiteral("4"));
    EXPECT_EQ(field("K2101/3"), QStringLiteral("27.0000"));
    EXPECT_EQ(field("K2110/3"), QStringLiteral("26.9790"));  // h7 on 27 mm: -0.021 mm (ISO 286-1)
    EXPECT_EQ(field("K2111/3"), QStringLiteral("27.0000"));
    EXPECT_EQ(field("K2142/3"), QStringLiteral("mm"));
    const std::vector<double> x = readings(db, 3);
    std::vector<double> values;
    int dates = 0;
    const QRegularExpression date(QStringLiteral("^\\d{2}\\.\\d{2}\\.\\d{4}/\\d{2}:\\d{2}:\\d{2}$"));
    for (const QString& line : lines) {
        if (line.startsWith(QLatin1String("K0001/3 "))) values.push_back(line.mid(8).toDouble());
        if (line.startsWith(QLatin1String("K0004/3 ")) && date.match(line.mid(8)).hasMatch()) ++dates;
    }
    ASSERT_EQ(values.size(), x.size());
    EXPECT_EQ(dates, static_cast<int>(x.size()));
    for (std::size_t i = 0; i < x.size(); ++i)
        EXPECT_NEAR(values[i], x[i], 5e-5) << "four decimals (K2022)";
}

// The adaptive loop's controller changes: a run on a plant of twice the model's gain adapts (simulate's own JSON
// lists where the controller changed); report --json gives each point the same changes at their chart points, with
// subgroups of 5 at the subgroup holding the part; the PDF is written. A damaged adaptations table leaves the report
// standing without them and says so on stderr.
TEST_F(ReportTest, ListsTheAdaptiveLoopsControllerChangesAtTheirChartPoints) {
    const QString db = path("adaptive.sqlite");
    const CliResult sim = runTrueturn({"simulate", "--preset", "paper-2012", "--delay", "1", "--plant-gain", "2",
                                       "--parts", "400", "--warmup", "0", "--seed", "1", "--db", db, "--json"});
    ASSERT_EQ(sim.exitCode, 0) << qPrintable(sim.err);
    std::vector<qint64> changedAt;
    for (const QJsonValue& a : sim.json()["adaptations"].toArray())
        if (a["applied"].toBool()) changedAt.push_back(a["part"].toInteger());
    ASSERT_GE(changedAt.size(), 2u);
    for (const int subgroup : {1, 5}) {
        const CliResult r = runTrueturn(
            {"report", "--db", db, "--subgroup", QString::number(subgroup), "--json", "--pdf", path("adaptive.pdf")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        EXPECT_TRUE(r.err.isEmpty()) << qPrintable(r.err);
        for (const QJsonValue& p : r.json()["points"].toArray()) {
            const QJsonArray changes = p["controller_changes"].toArray();
            ASSERT_EQ(static_cast<std::size_t>(changes.size()), changedAt.size());
            for (qsizetype i = 0; i < changes.size(); ++i) {
                EXPECT_EQ(changes[i]["run"].toInteger(), 1);
                EXPECT_EQ(changes[i]["part"].toInteger(), changedAt[static_cast<std::size_t>(i)]);
                // Every part measured and plausible here: part p is reading p, chart point ceil(p / n).
                EXPECT_EQ(changes[i]["chart_point"].toInteger(),
                          (changedAt[static_cast<std::size_t>(i)] - 1) / subgroup + 1);
            }
        }
    }
    {
        storage::Database history(storage::DatabaseConfig::sqlite(db));
        history.exec(QStringLiteral("UPDATE adaptations SET model_before = '{\"points\": 3}'"));
    }
    const CliResult damaged = runTrueturn({"report", "--db", db, "--json"});
    ASSERT_EQ(damaged.exitCode, 0) << qPrintable(damaged.err);
    EXPECT_TRUE(damaged.err.contains("the controller changes are not marked")) << qPrintable(damaged.err);
    EXPECT_TRUE(damaged.json()["points"].toArray()[0].toObject()["controller_changes"].toArray().isEmpty());
}

// A plant-wide history: runs tagged with their machine; the report reads one machine, or a date range.
TEST_F(ReportTest, MachinesAndDatesChooseTheRuns) {
    const QString db = path("plant.sqlite");
    for (const char* machine : {"lathe-a", "lathe-b"}) {
        const CliResult r = runTrueturn({"simulate", "--preset", "paper-2012", "--parts", "100", "--warmup", "0",
                                         "--machine", machine, "--db", db, "--json"});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    }
    const auto count = [&](const QStringList& extra) {
        const CliResult r = runTrueturn(QStringList{"report", "--db", db, "--point", "1", "--json"} + extra);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return r.json()["points"].toArray()[0].toObject()["n"].toInteger();
    };
    EXPECT_EQ(count({}), 200);
    EXPECT_EQ(count({"--machine", "lathe-b"}), 100);
    const QString today = QDateTime::currentDateTimeUtc().date().toString(Qt::ISODate);
    const QString tomorrow = QDateTime::currentDateTimeUtc().date().addDays(1).toString(Qt::ISODate);
    EXPECT_EQ(count({"--from", "2000-01-01", "--to", today}), 200) << "--to a day includes the whole day";
    test::expectRefused({"report", "--db", db, "--from", tomorrow}, "no measured part");
    test::expectRefused({"report", "--db", db, "--machine", "lathe-c"}, "no measured part");
    test::expectRefused({"report", "--db", db, "--from", "yesterday"}, "--from");
    test::expectRefused({"report", "--db", db, "--from", today, "--to", "2000-01-01"}, "--to");
}

TEST_F(ReportTest, BadInputIsRefusedWithTheReason) {
    test::expectRefused({"report", "--db", path("missing.sqlite")}, "does not exist");
    const QString db = history();
    test::expectRefused({"report", "--db", db, "--subgroup", "26"}, "--subgroup");
    test::expectRefused({"report", "--db", db, "--point", "0"}, "--point");
    test::expectRefused({"report", "--db", db, "--run", "7"}, "no measured part");
    test::expectRefused({"report"}, "--db");
}

}  // namespace
}  // namespace tt
