// `trueturn report`: argument parsing and output only. The readings come from the history (per point only the
// values the statistics need and their verdict counts, one pass: storage::queryPointReadings; every column of every
// reading for the CSV, DFQ and PDF files: storage::queryMeasurements), the statistics from runtime/reports'
// analyseReport (core/quality's analysePoint: chart, run rules, capability with the stored tolerance limits), the
// verdicts as stored with each reading; the files from runtime/reports too (the Reports page writes the same).
#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QTimeZone>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "core/quality/point_analysis.h"
#include "core/storage/history_store.h"
#include "core/storage/measurement_query.h"
#include "reports/report_pdf.h"
#include "runtime/reports/chart_adaptations.h"
#include "runtime/reports/point_report.h"
#include "runtime/reports/report_files.h"

namespace tt::cli {

namespace {

QJsonValue orNull(const std::optional<double>& v) {
    return v ? config::finiteOrNull(*v) : QJsonValue();
}

QJsonObject verdictsJson(const core::VerdictCounts& counts) {
    return {{QStringLiteral("good"), static_cast<qint64>(counts.good)},
            {QStringLiteral("rework"), static_cast<qint64>(counts.rework)},
            {QStringLiteral("scrap"), static_cast<qint64>(counts.scrap)}};
}

/// How many rule violations a point lists by default (their counts by rule are always given).
constexpr std::size_t kViolationsListed = 100;

/// The violations of a point: the first `listed` of them with their parts, and the counts by rule.
std::pair<QJsonArray, QJsonObject> violationsJson(const core::PointAnalysis& a, std::size_t listed) {
    QJsonArray violations;
    std::map<std::string, qint64> byRule;
    for (const core::PointViolation& v : a.violations) {
        const std::string rule = core::ruleCode(v.violation.set, v.violation.rule);
        ++byRule[rule];
        if (static_cast<std::size_t>(violations.size()) >= listed) continue;
        QJsonArray parts;
        for (const std::int64_t part : v.partNumbers)
            parts.append(static_cast<qint64>(part));
        violations.append(
            QJsonObject{{QStringLiteral("rule"), QString::fromStdString(rule)}, {QStringLiteral("parts"), parts}});
    }
    QJsonObject counts;
    for (const auto& [rule, n] : byRule)
        counts.insert(QString::fromStdString(rule), n);
    return {violations, counts};
}

/// [{run, part, kind, chart_point}]: where the adaptive loop changed the controller (chart_point 1-based).
QJsonArray controllerChangesJson(const runtime::PointReport& point) {
    QJsonArray changes;
    for (const runtime::ChartAdaptation& a : point.adaptations)
        changes.append(QJsonObject{{QStringLiteral("run"), static_cast<qint64>(a.runId)},
                                   {QStringLiteral("part"), static_cast<qint64>(a.record.partNumber)},
                                   {QStringLiteral("kind"), QString::fromStdString(a.record.kind)},
                                   {QStringLiteral("chart_point"), static_cast<qint64>(a.chartPoint + 1)}});
    return changes;
}

QJsonObject pointJson(const runtime::PointReport& point, std::size_t violationsListed) {
    const core::PointAnalysis& a = point.analysis;
    const core::ChartLimits& l = a.chart.limits;
    const auto [violations, violationCounts] = violationsJson(a, violationsListed);
    const std::optional<core::CapabilityStudy>& c = a.capability;
    const auto index = [&](double core::CapabilityIndices::*field) {
        return c ? config::finiteOrNull(c->indices.*field) : QJsonValue();
    };
    QJsonValue cpkInterval;
    if (c && c->indices.cpkInterval)
        cpkInterval = QJsonArray{config::finiteOrNull(c->indices.cpkInterval->lower),
                                 config::finiteOrNull(c->indices.cpkInterval->upper)};
    return {
        {QStringLiteral("point"), point.pointIndex + 1},
        {QStringLiteral("x_mm"), point.zMm},
        {QStringLiteral("n"), static_cast<qint64>(a.count)},
        {QStringLiteral("mean_mm"), config::finiteOrNull(a.meanMm)},
        {QStringLiteral("sigma_within_mm"), config::finiteOrNull(c ? c->sigmaWithinMm : l.sigmaWithinMm)},
        {QStringLiteral("sigma_overall_mm"), config::finiteOrNull(a.sigmaOverallMm)},
        {QStringLiteral("cp"), index(&core::CapabilityIndices::cp)},
        {QStringLiteral("cpk"), index(&core::CapabilityIndices::cpk)},
        {QStringLiteral("cpm"), c ? orNull(c->indices.cpm) : QJsonValue()},
        {QStringLiteral("pp"), index(&core::CapabilityIndices::pp)},
        {QStringLiteral("ppk"), index(&core::CapabilityIndices::ppk)},
        {QStringLiteral("cpk_ci"), cpkInterval},
        {QStringLiteral("method"),
         c ? QJsonValue(c->method == core::CapabilityMethod::Normal ? QStringLiteral("normal")
                                                                    : QStringLiteral("percentile"))
           : QJsonValue()},
        {QStringLiteral("normality_p"), c ? config::finiteOrNull(c->normality.pValue) : QJsonValue()},
        {QStringLiteral("limits"), QJsonObject{{QStringLiteral("centre"), l.location.centreMm},
                                               {QStringLiteral("ucl"), l.location.upperMm},
                                               {QStringLiteral("lcl"), l.location.lowerMm},
                                               {QStringLiteral("r_centre"), l.spread.centreMm},
                                               {QStringLiteral("r_ucl"), l.spread.upperMm},
                                               {QStringLiteral("r_lcl"), l.spread.lowerMm}}},
        {QStringLiteral("violations"), violations},
        {QStringLiteral("violation_count"), static_cast<qint64>(a.violations.size())},
        {QStringLiteral("violations_by_rule"), violationCounts},
        {QStringLiteral("verdicts"), verdictsJson(point.verdicts)},
        {QStringLiteral("controller_changes"), controllerChangesJson(point)},
    };
}

void printText(const QJsonArray& points) {
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9")
                  .arg(QStringLiteral("point"), 5)
                  .arg(QStringLiteral("x, mm"), 7)
                  .arg(QStringLiteral("n"), 7)
                  .arg(QStringLiteral("mean, mm"), 10)
                  .arg(QStringLiteral("σ within"), 9)
                  .arg(QStringLiteral("Cpk"), 6)
                  .arg(QStringLiteral("Ppk"), 6)
                  .arg(QStringLiteral("rules"), 5)
                  .arg(QStringLiteral("good/rework/scrap")));
    for (const QJsonValue& v : points) {
        const QJsonObject p = v.toObject();
        const QJsonObject verdicts = p[QStringLiteral("verdicts")].toObject();
        const auto index = [&](const char* key) {
            const QJsonValue x = p[QLatin1String(key)];
            return x.isDouble() ? QString::number(x.toDouble(), 'f', 2) : QStringLiteral("-");
        };
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9/%10/%11")
                      .arg(p[QStringLiteral("point")].toInt(), 5)
                      .arg(p[QStringLiteral("x_mm")].toDouble(), 7, 'f', 1)
                      .arg(p[QStringLiteral("n")].toInteger(), 7)
                      .arg(p[QStringLiteral("mean_mm")].toDouble(), 10, 'f', 4)
                      .arg(p[QStringLiteral("sigma_within_mm")].toDouble(), 9, 'f', 4)
                      .arg(index("cpk"), 6)
                      .arg(index("ppk"), 6)
                      .arg(p[QStringLiteral("violation_count")].toInteger(), 5)
                      .arg(verdicts[QStringLiteral("good")].toInteger())
                      .arg(verdicts[QStringLiteral("rework")].toInteger())
                      .arg(verdicts[QStringLiteral("scrap")].toInteger()));
    }
}

/// A --from/--to value as the stored UTC text: YYYY-MM-DD (the day's start; with `endOfDay` the next day's) or
/// an ISO 8601 date and time (UTC when it names no zone). Throws UsageError naming the option.
/// The adaptive loop's controller changes on each point's chart (the JSON's controller_changes, the PDF's marks); when
/// they cannot be read the report is written without them and stderr says why.
void markAdaptations(storage::Database& db, const std::vector<storage::PointReadings>& readings,
                     std::vector<runtime::PointReport>& reports) {
    try {
        storage::SqlHistoryStore store(db);
        runtime::placeAdaptations(reports, runtime::readRunAdaptations(store, readings));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trueturn report: the controller changes are not marked: %s\n", e.what());
    }
}

std::string utcBound(const QString& option, const QString& value, bool endOfDay) {
    QDateTime t;
    const QDate day = QDate::fromString(value, Qt::ISODate);
    if (day.isValid() && value.size() == 10) {
        t = QDateTime(endOfDay ? day.addDays(1) : day, QTime(0, 0), QTimeZone::utc());
    } else {
        t = QDateTime::fromString(value, Qt::ISODateWithMs);
        if (t.isValid() && t.timeSpec() == Qt::LocalTime) t.setTimeZone(QTimeZone::utc());
    }
    if (!t.isValid())
        throw UsageError("--" + option.toStdString() + ": '" + value.toStdString() +
                         "' is not a date (YYYY-MM-DD) or an ISO 8601 date and time");
    return t.toUTC().toString(Qt::ISODateWithMs).toStdString();
}

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("report"),
        QStringLiteral("The quality report of a stored history: per control point the control chart (I-MR, or "
                       "X-bar-R or X-bar-s of consecutive subgroups; phase-I limits from a baseline) with its limits "
                       "and Western Electric rule violations, "
                       "capability against the stored tolerance (Cp, Cpk with its 95 % interval, Cpm, Pp, Ppk; "
                       "ISO 22514-2 percentile method when Anderson-Darling rejects normality) and the verdict "
                       "counts; the readings as CSV and AQDEF (DFQ)."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The history: an SQLite file or postgresql://user@host:port/database."),
                     QStringLiteral("db"));
    parser.addOption(QStringLiteral("run"), QStringLiteral("Only this run (default: every run)."), QStringLiteral("n"));
    parser.addOption(QStringLiteral("machine"), QStringLiteral("Only the runs of this machine."),
                     QStringLiteral("name"));
    parser.addOption(QStringLiteral("from"),
                     QStringLiteral("Only parts stored from this date (YYYY-MM-DD, UTC) or ISO 8601 time."),
                     QStringLiteral("date"));
    parser.addOption(QStringLiteral("to"),
                     QStringLiteral("Only parts stored up to this date (YYYY-MM-DD, the whole day, UTC) or before "
                                    "this ISO 8601 time."),
                     QStringLiteral("date"));
    parser.addOption(QStringLiteral("point"), QStringLiteral("Only control point i, 1..16 (default: every point)."),
                     QStringLiteral("i"));
    parser.addOption(QStringLiteral("subgroup"),
                     QStringLiteral("Subgroup size of the chart: 1 for I-MR (default), 2..10 for X-bar-R, 11..25 for "
                                    "X-bar-s (unless --chart says)."),
                     QStringLiteral("n"), QStringLiteral("1"));
    parser.addOption(QStringLiteral("chart"),
                     QStringLiteral("The chart: xbar-r, xbar-s (with --subgroup 2..25) or imr (subgroup 1); default: "
                                    "by the subgroup size."),
                     QStringLiteral("kind"));
    parser.addOption(QStringLiteral("baseline"),
                     QStringLiteral("Phase I: control limits from the first N chart points (subgroups, or parts for "
                                    "I-MR), then held for the rest (phase II); default: all."),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("last"),
                     QStringLiteral("Per point only its newest N readings (parts measured there), 2..10000000: a "
                                    "capability window, as the Plant page's; not with --csv, --dfq or --pdf."),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("skip"),
                     QStringLiteral("With --last: leave out the newest M readings first (--last 125 --skip 125: the "
                                    "125 before the newest 125), 0..10000000."),
                     QStringLiteral("m"));
    parser.addOption(QStringLiteral("violations"),
                     QStringLiteral("How many rule violations each point lists with their parts: a number "
                                    "0..10000000 or all (default 100; their counts by rule are always given)."),
                     QStringLiteral("n|all"));
    parser.addOption(QStringLiteral("pdf"),
                     QStringLiteral("Also write the report as PDF: a title page (machine, job, dates, summary, every "
                                    "point's chart, signature line) and one page per control point."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("csv"),
                     QStringLiteral("Also write every reading as CSV (run, machine, part, time, point, x_mm, "
                                    "nominal_mm, measured_mm, deviation_mm, verdict)."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("dfq"),
                     QStringLiteral("Also write the readings as AQDEF (DFQ) for Q-DAS: one characteristic per "
                                    "control point with nominal, limits and unit, values with date and time."),
                     QStringLiteral("file"));
    parser.parse(arguments);

    const QString dbValue = parser.required(QStringLiteral("db"));
    if (!isPostgresOption(dbValue) && !QFile::exists(dbValue))
        throw UsageError("--db: '" + dbValue.toStdString() + "' does not exist");
    storage::MeasurementFilter filter;
    if (parser.isSet(QStringLiteral("run"))) filter.runId = parser.integer(QStringLiteral("run"), 1, 1LL << 53);
    if (parser.isSet(QStringLiteral("point")))
        filter.pointIndex = static_cast<int>(parser.integer(QStringLiteral("point"), 1, 16)) - 1;
    if (parser.isSet(QStringLiteral("machine"))) filter.machine = parser.value(QStringLiteral("machine")).toStdString();
    if (parser.isSet(QStringLiteral("from")))
        filter.fromUtc = utcBound(QStringLiteral("from"), parser.value(QStringLiteral("from")), false);
    if (parser.isSet(QStringLiteral("to")))
        filter.toUtc = utcBound(QStringLiteral("to"), parser.value(QStringLiteral("to")), true);
    if (filter.fromUtc && filter.toUtc && *filter.toUtc <= *filter.fromUtc)
        throw UsageError("--to: must come after --from");
    if (parser.isSet(QStringLiteral("last"))) {
        filter.lastReadings = parser.integer(QStringLiteral("last"), 2, 10000000);
        for (const char* file : {"csv", "dfq", "pdf"})
            if (parser.isSet(QString::fromLatin1(file)))
                throw UsageError(std::string("--last: a window of the statistics only, not with --") + file);
    }
    if (parser.isSet(QStringLiteral("skip"))) {
        if (!filter.lastReadings) throw UsageError("--skip: only with --last");
        filter.skipNewest = parser.integer(QStringLiteral("skip"), 0, 10000000);
    }
    std::size_t violationsListed = kViolationsListed;
    if (parser.isSet(QStringLiteral("violations")))
        violationsListed = parser.value(QStringLiteral("violations")) == QLatin1String("all")
                               ? std::numeric_limits<std::size_t>::max()
                               : static_cast<std::size_t>(parser.integer(QStringLiteral("violations"), 0, 10000000));
    const int subgroup = static_cast<int>(parser.integer(QStringLiteral("subgroup"), 1, 25));
    runtime::ReportChart chart = runtime::ReportChart::Automatic;
    if (parser.isSet(QStringLiteral("chart"))) {
        const QString kind = parser.choice(QStringLiteral("chart"),
                                           {QStringLiteral("xbar-r"), QStringLiteral("xbar-s"), QStringLiteral("imr")});
        chart = kind == QStringLiteral("imr")      ? runtime::ReportChart::IndividualsMR
                : kind == QStringLiteral("xbar-s") ? runtime::ReportChart::XbarStdDev
                                                   : runtime::ReportChart::XbarRange;
    }
    const std::size_t baseline =
        parser.isSet(QStringLiteral("baseline"))
            ? static_cast<std::size_t>(parser.integer(QStringLiteral("baseline"), 2, core::kMaxSeriesValues))
            : 0;
    core::PointAnalysisSettings settings;
    try {
        settings = runtime::reportSettings(subgroup, chart, baseline);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--chart: ") + e.what());
    }

    std::unique_ptr<storage::Database> db;
    std::vector<storage::PointReadings> readings;
    std::vector<storage::MeasurementRow> rows;  // every column of every reading: only for the files and the PDF
    std::vector<core::RunSummary> runs;
    std::optional<core::VerdictCounts> partVerdicts;  // every chosen point of each part: without --point or --last
    const bool pdf = parser.isSet(QStringLiteral("pdf"));
    const bool files = parser.isSet(QStringLiteral("csv")) || parser.isSet(QStringLiteral("dfq")) || pdf;
    try {
        // PostgreSQL in read-only transactions: a report may read a hot standby, and never changes the plant's
        // history. (An SQLite history is the terminal's own file: opened as before, brought up to date.)
        storage::DatabaseConfig config = databaseConfigFromOption(dbValue);
        config.readOnly = config.kind == storage::DatabaseConfig::Kind::Postgres;
        db = std::make_unique<storage::Database>(config);
        readings = storage::queryPointReadings(*db, filter);
        if (!filter.pointIndex && !filter.lastReadings) partVerdicts = storage::queryPartVerdicts(*db, filter);
        if (files) rows = storage::queryMeasurements(*db, filter);
        if (pdf) runs = storage::SqlHistoryStore(*db).runs();
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    if (readings.empty() || (files && rows.empty()))
        throw UsageError("the history holds no measured part for this choice of run, machine, dates and point");

    std::vector<runtime::PointReport> reports = runtime::analyseReport(readings, settings);
    markAdaptations(*db, readings, reports);
    QJsonArray points;
    for (const runtime::PointReport& point : reports)
        points.append(pointJson(point, violationsListed));
    if (parser.isSet(QStringLiteral("csv"))) runtime::writeMeasurementsCsv(parser.value(QStringLiteral("csv")), rows);
    if (parser.isSet(QStringLiteral("dfq"))) runtime::writeMeasurementsDfq(parser.value(QStringLiteral("dfq")), rows);
    if (parser.isSet(QStringLiteral("pdf")))
        reports::ReportPdf::write(parser.value(QStringLiteral("pdf")), reports::reportHeaderOf(rows, runs), reports);
    if (parser.json()) {
        QJsonObject out{{QStringLiteral("subgroup"), settings.subgroupSize},
                        {QStringLiteral("chart"),
                         QString::fromStdString(runtime::chartKindName(reports.front().analysis.chart.limits.kind))},
                        {QStringLiteral("points"), points}};
        if (filter.runId) out.insert(QStringLiteral("run"), static_cast<qint64>(*filter.runId));
        if (partVerdicts) out.insert(QStringLiteral("part_verdicts"), verdictsJson(*partVerdicts));
        printJson(out);
    } else {
        printText(points);
    }
    return kExitOk;
}

}  // namespace

Command makeReportCommand() {
    return {QStringLiteral("report"),
            QStringLiteral("Quality report of a stored history: control charts, rule violations, capability and "
                           "verdicts per control point, CSV and AQDEF (DFQ) of the readings, PDF report"),
            run, [](const QStringList& arguments) {
                return std::any_of(arguments.begin(), arguments.end(), [](const QString& a) {
                    return a == QStringLiteral("--pdf") || a.startsWith(QStringLiteral("--pdf="));
                });
            }};
}

}  // namespace tt::cli
