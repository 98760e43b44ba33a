// The report's reads of a generated history of 20,000 parts (storage::writeSyntheticHistory), on SQLite and
// PostgreSQL: what SQL aggregates (counts, mean, sigma, extremes, verdict counts) and what the one-pass point
// reading returns equal the same figures computed here in C++ from the raw rows of the measurements table.
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <vector>

#include "core/storage/history_store.h"
#include "core/storage/measurement_query.h"
#include "core/storage/synthetic_history.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

/// One plausible reading as the raw tables hold it.
struct RawReading {
    std::int64_t runId = 0;
    std::int64_t partNumber = 0;
    double timeS = 0.0;
    double valueMm = 0.0;
    std::string verdict;
    double lowerMm = 0.0;
    double upperMm = 0.0;
};

/// The plausible readings of every point straight from the tables (no filter in SQL but the join and the run,
/// the plausibility decided here), in run and part order.
std::map<int, std::vector<RawReading>> rawReadings(Database& db, std::optional<std::int64_t> run = std::nullopt) {
    QSqlQuery q =
        db.exec(QStringLiteral("SELECT m.point_index, p.run_id, p.part_number, m.measured_s, m.measured_mm,"
                               " m.reason_kind, m.verdict, m.lower_limit_mm, m.upper_limit_mm"
                               " FROM measurements m JOIN parts p ON p.id = m.part_id"));
    std::map<int, std::vector<RawReading>> points;
    while (q.next()) {
        const QString kind = q.value(5).toString();
        if (q.value(4).isNull() || kind == u"implausible" || kind == u"not-finite" || kind == u"not-a-number") continue;
        RawReading r{q.value(1).toLongLong(),
                     q.value(2).toLongLong(),
                     q.value(3).toDouble(),
                     q.value(4).toDouble(),
                     q.value(6).toString().toStdString(),
                     q.value(7).toDouble(),
                     q.value(8).toDouble()};
        if (run && r.runId != *run) continue;
        points[q.value(0).toInt()].push_back(r);
    }
    for (auto& [index, readings] : points)
        std::sort(readings.begin(), readings.end(), [](const RawReading& a, const RawReading& b) {
            return std::tie(a.runId, a.partNumber) < std::tie(b.runId, b.partNumber);
        });
    return points;
}

std::int64_t countVerdict(const std::vector<RawReading>& readings, const char* verdict) {
    return std::count_if(readings.begin(), readings.end(), [&](const RawReading& r) { return r.verdict == verdict; });
}

class ReportAggregatesTest : public ::testing::TestWithParam<std::string> {
protected:
    static constexpr std::int64_t kParts = 20000;

    SyntheticHistorySpec spec() const {
        SyntheticHistorySpec s;
        s.parts = kParts;
        s.runs = 4;
        s.machines = 2;
        s.seed = 20261125;
        s.implausibleFraction = 0.002;
        return s;
    }
};

/// The SQL aggregates of every point against the raw rows.
void checkAggregates(Database& db, std::int64_t parts) {
    const auto raw = rawReadings(db);
    const std::vector<PointAggregate> aggregates = queryPointAggregates(db, {});
    ASSERT_EQ(aggregates.size(), 5u);
    for (const PointAggregate& a : aggregates) {
        SCOPED_TRACE("point index " + std::to_string(a.pointIndex));
        const std::vector<RawReading>& r = raw.at(a.pointIndex);
        std::vector<double> v;
        for (const RawReading& x : r)
            v.push_back(x.valueMm);
        // Counts and extremes are exact; about 0.2 % of the readings are refused and not counted.
        EXPECT_EQ(a.count, static_cast<std::int64_t>(v.size()));
        EXPECT_LT(a.count, parts);
        EXPECT_GT(a.count, parts * 99 / 100);
        EXPECT_EQ(a.minMm, *std::min_element(v.begin(), v.end()));
        EXPECT_EQ(a.maxMm, *std::max_element(v.begin(), v.end()));
        // Mean and sample sigma by the two-pass textbook formulas here; SQL sums in another order, so they agree
        // to rounding: 20,000 values near 27 mm, double precision -> well within 1e-9 mm.
        const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
        double ss = 0.0;
        for (double x : v)
            ss += (x - mean) * (x - mean);
        const double sigma = std::sqrt(ss / static_cast<double>(v.size() - 1));
        EXPECT_NEAR(a.meanMm, mean, 1e-9);
        EXPECT_NEAR(a.sigmaOverallMm, sigma, 1e-9);
        // The generated process: scatter 0.003 mm, residual drift about 0.001 mm (synthetic_history.h).
        EXPECT_NEAR(a.sigmaOverallMm, 0.0035, 0.001);
        EXPECT_EQ(a.verdicts.good, countVerdict(r, "good"));
        EXPECT_EQ(a.verdicts.rework, countVerdict(r, "rework"));
        EXPECT_EQ(a.verdicts.scrap, countVerdict(r, "scrap"));
        EXPECT_EQ(a.verdicts.total(), a.count) << "every plausible generated reading has a verdict";
        EXPECT_GT(a.verdicts.scrap, 0) << "h7 is tighter than the generated scatter";
        EXPECT_GT(a.verdicts.rework, 0);
    }
}

/// The one-pass reading of point 3 (over every run and over the last run) against the raw rows.
void checkPointReadings(Database& db, const SyntheticHistoryResult& written) {
    for (const std::optional<std::int64_t> run : {std::optional<std::int64_t>(), std::optional(written.lastRunId)}) {
        SCOPED_TRACE(run ? "run " + std::to_string(*run) : std::string("every run"));
        const auto raw = rawReadings(db, run);
        MeasurementFilter filter;
        filter.pointIndex = 2;
        filter.runId = run;
        const std::vector<PointReadings> points = queryPointReadings(db, filter);
        ASSERT_EQ(points.size(), 1u);
        const PointReadings& p = points.front();
        const std::vector<RawReading>& r = raw.at(2);
        EXPECT_EQ(p.pointIndex, 2);
        ASSERT_EQ(p.valuesMm.size(), r.size());
        for (std::size_t i = 0; i < r.size(); ++i) {
            ASSERT_EQ(p.valuesMm[i], r[i].valueMm) << "reading " << i;  // the same doubles, the same order
            ASSERT_EQ(p.partNumbers[i], r[i].partNumber) << "reading " << i;
            ASSERT_EQ(p.timesS[i], r[i].timeS) << "reading " << i;
        }
        EXPECT_EQ(p.verdicts.good, countVerdict(r, "good"));
        EXPECT_EQ(p.verdicts.rework, countVerdict(r, "rework"));
        EXPECT_EQ(p.verdicts.scrap, countVerdict(r, "scrap"));
        // h7 on 27 mm (ISO 286-1: es 0, ei -0.021 mm) as generated; the point at x = 10 + 130 * 2 / 4 mm.
        ASSERT_TRUE(p.lowerLimitMm && p.upperLimitMm);
        EXPECT_DOUBLE_EQ(*p.lowerLimitMm, 26.979);
        EXPECT_DOUBLE_EQ(*p.upperLimitMm, 27.0);
        EXPECT_DOUBLE_EQ(p.limitsNominalMm, 27.0);
        EXPECT_DOUBLE_EQ(p.nominalMm, 27.0);
        EXPECT_DOUBLE_EQ(p.zMm, 75.0);
    }
}

TEST_P(ReportAggregatesTest, SqlAggregatesAndPointReadingsEqualTheRawRows) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    db.migrate(historySchema());
    const SyntheticHistoryResult written = writeSyntheticHistory(db, spec());
    EXPECT_EQ(written.parts, kParts);
    EXPECT_EQ(written.readings, kParts * 5);
    {
        SCOPED_TRACE("aggregates");
        checkAggregates(db, kParts);
    }
    {
        SCOPED_TRACE("point readings");
        checkPointReadings(db, written);
    }
}

TEST_P(ReportAggregatesTest, TheOnePointReadUsesTheCoveringIndex) {
    if (GetParam() != "sqlite") GTEST_SKIP() << "the plan is SQLite's; PostgreSQL chooses by table statistics";
    test::ScratchDatabase scratch(GetParam());
    Database db(scratch.config());
    db.migrate(historySchema());
    QSqlQuery q = db.exec(QStringLiteral(
        "EXPLAIN QUERY PLAN SELECT m.point_index, p.run_id, p.part_number, m.measured_s, m.measured_mm, m.verdict"
        " FROM measurements m JOIN parts p ON p.id = m.part_id WHERE m.measured_mm IS NOT NULL AND"
        " m.point_index = 0"));
    QString plan;
    while (q.next())
        plan += q.value(3).toString() + QLatin1Char('\n');
    EXPECT_TRUE(plan.contains(QStringLiteral("COVERING INDEX measurements_point_values"))) << plan.toStdString();
}

TEST(SyntheticHistory, RefusesASpecOutOfRange) {
    test::ScratchDatabase scratch("sqlite");
    Database db(scratch.config());
    db.migrate(historySchema());
    SyntheticHistorySpec s;
    s.parts = 0;
    EXPECT_THROW(writeSyntheticHistory(db, s), std::invalid_argument);
    s.parts = 10;
    s.runs = 11;
    EXPECT_THROW(writeSyntheticHistory(db, s), std::invalid_argument);
    s.runs = 1;
    s.points = 17;
    EXPECT_THROW(writeSyntheticHistory(db, s), std::invalid_argument);
    s.points = 5;
    s.lowerDeviationMm = 0.01;  // above es = 0
    EXPECT_THROW(writeSyntheticHistory(db, s), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, ReportAggregatesTest, ::testing::ValuesIn(test::backends()));

}  // namespace
}  // namespace tt::storage
