// The quality report of one control point over a big history (issue 12: 1,000,000 parts x 5 points answered in
// under 2 s on SQLite and PostgreSQL). The history is built beforehand by scripts/make-big-history.sh, never
// here and never in CI; the benchmarks skip when it is not named:
//   TRUETURN_BIG_HISTORY_SQLITE  the SQLite file
//   TRUETURN_BIG_HISTORY_PG      postgresql://user@host:port/database (or TRUETURN_PG_URL's server, database
//                                "trueturn_big_history", when only that is set)
// Two figures per database: the whole `trueturn report --db DB --point 1 --json` process (wall time, what the
// quality engineer waits for), and the in-process read + analysis (storage::queryPointReadings, analysePoint).
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QProcess>
#include <QString>
#include <memory>
#include <optional>

#include "core/quality/point_analysis.h"
#include "core/storage/measurement_query.h"

namespace {

using namespace tt;

/// QtSql needs an application object for its driver plugins.
void ensureApplication() {
    static int argc = 1;
    static char name[] = "trueturn_bench";
    static char* argv[] = {name, nullptr};
    static const std::unique_ptr<QCoreApplication> app =
        QCoreApplication::instance() ? nullptr : std::make_unique<QCoreApplication>(argc, argv);
}

/// The --db value of the big history on `backend`, none when it is not configured.
std::optional<QString> bigHistory(const char* backend) {
    if (QStringLiteral("sqlite") == QLatin1String(backend)) {
        const QString path = qEnvironmentVariable("TRUETURN_BIG_HISTORY_SQLITE");
        return path.isEmpty() ? std::nullopt : std::optional(path);
    }
    const QString url = qEnvironmentVariable("TRUETURN_BIG_HISTORY_PG");
    if (!url.isEmpty()) return url;
    const QString server = qEnvironmentVariable("TRUETURN_PG_URL");
    if (server.isEmpty()) return std::nullopt;
    return server.left(server.lastIndexOf(QLatin1Char('/'))) + QStringLiteral("/trueturn_big_history");
}

storage::DatabaseConfig configOf(const QString& db) {
    return db.startsWith(QStringLiteral("postgres")) ? storage::DatabaseConfig::postgresUrl(db)
                                                     : storage::DatabaseConfig::sqlite(db);
}

/// `trueturn report --db DB --point 1 --json`, the real binary, its whole output read.
void BM_ReportCommandOnePoint(benchmark::State& state, const char* backend) {
    ensureApplication();
    const std::optional<QString> db = bigHistory(backend);
    if (!db) {
        state.SkipWithError("no big history: run scripts/make-big-history.sh and export what it prints");
        return;
    }
    std::int64_t bytes = 0;
    for (auto _ : state) {
        QProcess report;
        report.start(QStringLiteral(TRUETURN_BINARY),
                     {QStringLiteral("report"), QStringLiteral("--db"), *db, QStringLiteral("--point"),
                      QStringLiteral("1"), QStringLiteral("--json")});
        if (!report.waitForFinished(600000) || report.exitCode() != 0) {
            state.SkipWithError(("trueturn report failed: " + report.readAllStandardError().toStdString()).c_str());
            return;
        }
        bytes = report.readAllStandardOutput().size();
    }
    state.counters["json_bytes"] = static_cast<double>(bytes);
}

/// The floor the report is held against (issue 24, item 7: at most 1.5 times it): the sqlite3 shell reading point
/// 1's diameters in part order from the same file, printed into a pipe that is read whole.
void BM_SqliteShellFloorOnePoint(benchmark::State& state) {
    const std::optional<QString> db = bigHistory("sqlite");
    if (!db) {
        state.SkipWithError("no big history: run scripts/make-big-history.sh and export what it prints");
        return;
    }
    std::int64_t bytes = 0;
    for (auto _ : state) {
        QProcess shell;
        shell.start(QStringLiteral("sqlite3"),
                    {*db, QStringLiteral("SELECT m.measured_mm FROM measurements m JOIN parts p ON p.id = m.part_id "
                                         "WHERE m.point_index = 0 ORDER BY p.run_id, p.part_number")});
        if (!shell.waitForFinished(600000) || shell.exitCode() != 0) {
            state.SkipWithError("the sqlite3 shell (package sqlite3) failed or is missing");
            return;
        }
        bytes = shell.readAllStandardOutput().size();
    }
    state.counters["text_bytes"] = static_cast<double>(bytes);
}

/// The in-process part: point 1's readings from the database and its whole analysis (I-MR, Western Electric
/// rules, capability against the stored tolerance).
void BM_ReportReadAndAnalyseOnePoint(benchmark::State& state, const char* backend) {
    ensureApplication();
    const std::optional<QString> dbValue = bigHistory(backend);
    if (!dbValue) {
        state.SkipWithError("no big history: run scripts/make-big-history.sh and export what it prints");
        return;
    }
    storage::Database db(configOf(*dbValue));
    storage::MeasurementFilter filter;
    filter.pointIndex = 0;
    std::size_t readings = 0;
    for (auto _ : state) {
        const std::vector<storage::PointReadings> points = storage::queryPointReadings(db, filter);
        if (points.size() != 1) {
            state.SkipWithError("the big history has no readings of point 1");
            return;
        }
        const storage::PointReadings& p = points.front();
        core::PointAnalysisSettings settings;
        if (p.lowerLimitMm && p.upperLimitMm)
            settings.spec = core::SpecLimits{*p.lowerLimitMm, *p.upperLimitMm, p.limitsNominalMm};
        core::MeasuredSeries series;
        series.valuesMm = p.valuesMm;
        series.partNumbers = p.partNumbers;
        series.timesS = p.timesS;
        const core::PointAnalysis analysis = core::analysePoint(series, settings);
        benchmark::DoNotOptimize(analysis.capability);
        readings = p.valuesMm.size();
    }
    state.counters["readings"] = static_cast<double>(readings);
}

BENCHMARK_CAPTURE(BM_ReportCommandOnePoint, sqlite, "sqlite")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SqliteShellFloorOnePoint)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ReportCommandOnePoint, postgres, "postgres")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ReportReadAndAnalyseOnePoint, sqlite, "sqlite")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ReportReadAndAnalyseOnePoint, postgres, "postgres")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
