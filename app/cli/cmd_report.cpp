// `trueturn report`: argument parsing and output only. The readings come from the history (per point only the
// values the statistics need and their verdict counts, one pass: storage::queryPointReadings; every column of every
// reading for the CSV and DFQ files: storage::queryMeasurements), the statistics from core/quality's analysePoint
// (chart, run rules, capability with the stored tolerance limits), the verdicts as stored with each reading.
#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QTextStream>
#include <QTimeZone>
#include <map>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "core/quality/point_analysis.h"
#include "core/storage/measurement_query.h"

namespace tt::cli {

namespace {

/// The specification limits of a point: the stored tolerance of its latest reading that has one, the
/// nominal as target; none when no reading has a tolerance.
std::optional<core::SpecLimits> specOf(const storage::PointReadings& point) {
    if (point.lowerLimitMm && point.upperLimitMm)
        return core::SpecLimits{*point.lowerLimitMm, *point.upperLimitMm, point.limitsNominalMm};
    return std::nullopt;
}

core::MeasuredSeries seriesOf(const storage::PointReadings& point) {
    core::MeasuredSeries series;
    series.valuesMm = point.valuesMm;
    series.partNumbers = point.partNumbers;
    series.timesS = point.timesS;
    return series;
}

QJsonValue orNull(const std::optional<double>& v) {
    return v ? config::finiteOrNull(*v) : QJsonValue();
}

QJsonObject verdictsJson(const storage::PointReadings& point) {
    return {{QStringLiteral("good"), static_cast<qint64>(point.verdicts.good)},
            {QStringLiteral("rework"), static_cast<qint64>(point.verdicts.rework)},
            {QStringLiteral("scrap"), static_cast<qint64>(point.verdicts.scrap)}};
}

QJsonObject pointJson(const storage::PointReadings& point, const core::PointAnalysisSettings& base) {
    core::PointAnalysisSettings settings = base;
    settings.spec = specOf(point);
    core::PointAnalysis a;
    try {
        a = core::analysePoint(seriesOf(point), settings);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("point " + std::to_string(point.pointIndex + 1) + ": " + e.what());
    }
    const core::ChartLimits& l = a.chart.limits;
    QJsonArray violations;
    for (const core::PointViolation& v : a.violations) {
        QJsonArray parts;
        for (const std::int64_t part : v.partNumbers)
            parts.append(static_cast<qint64>(part));
        violations.append(QJsonObject{
            {QStringLiteral("rule"), QString::fromStdString(core::ruleCode(v.violation.set, v.violation.rule))},
            {QStringLiteral("parts"), parts}});
    }
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
        {QStringLiteral("verdicts"), verdictsJson(point)},
    };
}

QString csvNumber(double v) {
    return QString::number(v, 'f', 4);
}

/// run, machine, part, time (ISO 8601), point, x_mm, nominal_mm, measured_mm, deviation_mm, verdict.
void writeCsv(const QString& path, const std::vector<storage::MeasurementRow>& rows) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        throw std::runtime_error("--csv: cannot write '" + path.toStdString() +
                                 "': " + file.errorString().toStdString());
    QTextStream out(&file);
    out << "run,machine,part,time,point,x_mm,nominal_mm,measured_mm,deviation_mm,verdict\n";
    for (const storage::MeasurementRow& r : rows) {
        QString machine = QString::fromStdString(r.machine);
        if (machine.contains(QLatin1Char(',')) || machine.contains(QLatin1Char('"')))
            machine = QLatin1Char('"') + machine.replace(QLatin1String("\""), QLatin1String("\"\"")) + QLatin1Char('"');
        out << r.runId << ',' << machine << ',' << r.partNumber << ',' << QString::fromStdString(r.recordedAt) << ','
            << r.pointIndex + 1 << ',' << csvNumber(r.zMm) << ',' << csvNumber(r.nominalMm) << ','
            << csvNumber(r.measuredMm) << ',' << csvNumber(r.measuredMm - r.nominalMm) << ','
            << (r.verdict ? QString::fromStdString(core::toleranceVerdictName(*r.verdict)) : QString()) << '\n';
    }
    out.flush();
    if (file.error() != QFileDevice::NoError)
        throw std::runtime_error("--csv: writing '" + path.toStdString() +
                                 "' failed: " + file.errorString().toStdString());
}

/// AQDEF (Q-DAS ASCII transfer format) date/time: DD.MM.YYYY/HH:MM:SS, from the stored ISO 8601 UTC.
QString dfqTime(const std::string& iso) {
    const QDateTime t = QDateTime::fromString(QString::fromStdString(iso), Qt::ISODateWithMs);
    return t.isValid() ? t.toUTC().toString(QStringLiteral("dd.MM.yyyy/HH:mm:ss")) : QString();
}

/// AQDEF for Q-DAS (one key per line, "/i" = characteristic i): K0100 number of characteristics; K1001/K1002
/// part number and description; per control point K2001/K2002 characteristic number and description, K2022
/// decimal places, K2101 nominal, K2110/K2111 lower/upper specification limit, K2142 unit; then each
/// reading as K0001/i value with K0004/i date/time, part by part.
void writeDfq(const QString& path, const std::vector<storage::MeasurementRow>& rows,
              const std::vector<storage::PointReadings>& points) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        throw std::runtime_error("--dfq: cannot write '" + path.toStdString() +
                                 "': " + file.errorString().toStdString());
    QTextStream out(&file);
    out.setEncoding(QStringConverter::Latin1);
    std::map<int, int> characteristic;  // point index -> K-field index 1..
    for (const storage::PointReadings& point : points)
        characteristic[point.pointIndex] = static_cast<int>(characteristic.size()) + 1;
    out << "K0100 " << characteristic.size() << "\r\n";
    out << "K1001 "
        << (rows.front().machine.empty() ? QStringLiteral("shaft") : QString::fromStdString(rows.front().machine))
        << "\r\n";
    out << "K1002 TrueTurn shaft, run(s) " << rows.front().runId << ".." << rows.back().runId << "\r\n";
    for (const storage::PointReadings& point : points) {
        const int index = point.pointIndex;
        const QString k = QStringLiteral("/%1 ").arg(characteristic[index]);
        const std::optional<core::SpecLimits> spec = specOf(point);
        out << "K2001" << k << "P" << index + 1 << "\r\n";
        out << "K2002" << k << "Diameter at x = " << QString::number(point.zMm, 'f', 1) << " mm\r\n";
        out << "K2022" << k << "4\r\n";
        out << "K2101" << k << QString::number(point.nominalMm, 'f', 4) << "\r\n";
        if (spec) {
            out << "K2110" << k << QString::number(spec->lowerMm, 'f', 4) << "\r\n";
            out << "K2111" << k << QString::number(spec->upperMm, 'f', 4) << "\r\n";
        }
        out << "K2142" << k << "mm\r\n";
    }
    for (const storage::MeasurementRow& r : rows) {
        const QString k = QStringLiteral("/%1 ").arg(characteristic[r.pointIndex]);
        out << "K0001" << k << QString::number(r.measuredMm, 'f', 4) << "\r\n";
        out << "K0004" << k << dfqTime(r.recordedAt) << "\r\n";
    }
    out.flush();
    if (file.error() != QFileDevice::NoError)
        throw std::runtime_error("--dfq: writing '" + path.toStdString() +
                                 "' failed: " + file.errorString().toStdString());
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
                      .arg(p[QStringLiteral("violations")].toArray().size(), 5)
                      .arg(verdicts[QStringLiteral("good")].toInteger())
                      .arg(verdicts[QStringLiteral("rework")].toInteger())
                      .arg(verdicts[QStringLiteral("scrap")].toInteger()));
    }
}

/// A --from/--to value as the stored UTC text: YYYY-MM-DD (the day's start; with `endOfDay` the next day's) or
/// an ISO 8601 date and time (UTC when it names no zone). Throws UsageError naming the option.
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
                       "X-bar-R of consecutive subgroups) with its limits and Western Electric rule violations, "
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
                     QStringLiteral("Subgroup size of the chart: 1 for I-MR (default), 2..25 for X-bar-R."),
                     QStringLiteral("n"), QStringLiteral("1"));
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
    core::PointAnalysisSettings settings;
    settings.subgroupSize = static_cast<int>(parser.integer(QStringLiteral("subgroup"), 1, 25));

    std::unique_ptr<storage::Database> db;
    std::vector<storage::PointReadings> readings;
    std::vector<storage::MeasurementRow> rows;  // every column of every reading: only for the CSV and DFQ files
    const bool files = parser.isSet(QStringLiteral("csv")) || parser.isSet(QStringLiteral("dfq"));
    try {
        db = std::make_unique<storage::Database>(databaseConfigFromOption(dbValue));
        readings = storage::queryPointReadings(*db, filter);
        if (files) rows = storage::queryMeasurements(*db, filter);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    if (readings.empty() || (files && rows.empty()))
        throw UsageError("the history holds no measured part for this choice of run, machine, dates and point");

    QJsonArray points;
    for (const storage::PointReadings& point : readings)
        points.append(pointJson(point, settings));
    if (parser.isSet(QStringLiteral("csv"))) writeCsv(parser.value(QStringLiteral("csv")), rows);
    if (parser.isSet(QStringLiteral("dfq"))) writeDfq(parser.value(QStringLiteral("dfq")), rows, readings);
    if (parser.json()) {
        QJsonObject out{{QStringLiteral("subgroup"), settings.subgroupSize}, {QStringLiteral("points"), points}};
        if (filter.runId) out.insert(QStringLiteral("run"), static_cast<qint64>(*filter.runId));
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
                           "verdicts per control point, CSV and AQDEF (DFQ) of the readings"),
            run};
}

}  // namespace tt::cli
