// `trueturn identify`: argument parsing and output only. The series is read from the history and fitted
// by core::identifyStoredDisturbance (core/control/disturbance_identification.h, prediction-error method
// in core/control/arma_identification.h).
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "core/control/disturbance_identification.h"
#include "core/control/run_to_run_plant.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"

namespace tt::cli {

namespace {

QJsonArray numbers(const std::vector<double>& values) {
    QJsonArray a;
    for (double v : values)
        a.append(config::finiteOrNull(v));
    return a;
}

/// The fit in the presets' disturbance form: [{"type": "shaping_filter", "numerator", "denominator",
/// "variance_mm2"}] (or white noise for ARMA(0, 0)).
QJsonArray shapingFilterJson(const core::ArmaFit& fit) {
    const core::DisturbanceModel model = fit.disturbanceModel();
    const core::DisturbanceComponent& c = model.components().front();
    if (!c.filter())
        return QJsonArray{QJsonObject{{QStringLiteral("type"), QStringLiteral("white")},
                                      {QStringLiteral("variance_mm2"), c.stationaryVarianceMm2()}}};
    return QJsonArray{QJsonObject{{QStringLiteral("type"), QStringLiteral("shaping_filter")},
                                  {QStringLiteral("numerator"), numbers(c.filter()->numerator())},
                                  {QStringLiteral("denominator"), numbers(c.filter()->denominator())},
                                  {QStringLiteral("variance_mm2"), c.stationaryVarianceMm2()}}};
}

QJsonObject toJson(const core::DisturbanceIdentification& id) {
    const core::ArmaFit& f = id.fit;
    return QJsonObject{
        {QStringLiteral("run_id"), static_cast<qint64>(id.series.runId)},
        {QStringLiteral("point"), id.series.point + 1},
        {QStringLiteral("parts"), QJsonObject{{QStringLiteral("from"), static_cast<qint64>(id.series.firstPart)},
                                              {QStringLiteral("to"), static_cast<qint64>(id.series.lastPart)},
                                              {QStringLiteral("count"), static_cast<qint64>(f.values)}}},
        {QStringLiteral("ar"), numbers(f.ar)},
        {QStringLiteral("ma"), numbers(f.ma)},
        {QStringLiteral("std_errors"),
         QJsonObject{{QStringLiteral("ar"), numbers(f.arStdErr)}, {QStringLiteral("ma"), numbers(f.maStdErr)}}},
        {QStringLiteral("mean_mm"), config::finiteOrNull(f.meanMm)},
        {QStringLiteral("noise_variance"), config::finiteOrNull(f.noiseVarianceMm2)},
        {QStringLiteral("ljung_box_q"), config::finiteOrNull(f.ljungBoxQ)},
        {QStringLiteral("ljung_box_lags"), f.ljungBoxLags},
        {QStringLiteral("ljung_box_p"), config::finiteOrNull(f.ljungBoxP)},
        {QStringLiteral("disturbance"), shapingFilterJson(f)}};
}

QString list(const std::vector<double>& values, const std::vector<double>& errors) {
    QStringList parts;
    for (std::size_t i = 0; i < values.size(); ++i)
        parts << QStringLiteral("%1 ± %2").arg(values[i], 0, 'f', 4).arg(errors[i], 0, 'f', 4);
    return parts.isEmpty() ? QStringLiteral("none") : parts.join(QStringLiteral(", "));
}

void printText(const core::DisturbanceIdentification& id) {
    const core::ArmaFit& f = id.fit;
    printLine(QStringLiteral("Disturbance of run %1, point %2: parts %3 .. %4 (%5 values), mean %6 mm")
                  .arg(id.series.runId)
                  .arg(id.series.point + 1)
                  .arg(id.series.firstPart)
                  .arg(id.series.lastPart)
                  .arg(f.values)
                  .arg(f.meanMm, 0, 'f', 4));
    printLine(QStringLiteral("AR: %1").arg(list(f.ar, f.arStdErr)));
    printLine(QStringLiteral("MA: %1").arg(list(f.ma, f.maStdErr)));
    printLine(QStringLiteral("noise variance %1 mm², Ljung-Box Q = %2 over %3 lags, p = %4")
                  .arg(f.noiseVarianceMm2, 0, 'g', 4)
                  .arg(f.ljungBoxQ, 0, 'f', 2)
                  .arg(f.ljungBoxLags)
                  .arg(f.ljungBoxP, 0, 'g', 3));
    printLine(QStringLiteral("as the preset's disturbance: ") +
              QString::fromUtf8(QJsonDocument(shapingFilterJson(f)).toJson(QJsonDocument::Compact)));
}

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("identify"),
                         QStringLiteral("Fits the part-to-part disturbance of a stored run (measured deviation minus "
                                        "k_i x the correction each part received) as an ARMA model by the "
                                        "prediction-error method, with standard errors and the Ljung-Box test of "
                                        "the residuals, and prints it as the presets' shaping filter."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The history: an SQLite file or postgresql://user@host:port/database."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("run"), QStringLiteral("The run's id (default: the newest run)."),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("point"), QStringLiteral("Control point, 1..16 (default 1)."), QStringLiteral("i"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("ar"), QStringLiteral("AR order p, 0..4 (default 1)."), QStringLiteral("p"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("ma"), QStringLiteral("MA order q, 0..4 (default 1)."), QStringLiteral("q"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("gain"),
                     QStringLiteral("k_i, diameter change per radial correction, 0.1..100 (default 2)."),
                     QStringLiteral("k"), QStringLiteral("2"));
    parser.parse(arguments);

    const QString database = parser.required(QStringLiteral("db"));
    if (!isPostgresOption(database) && !QFileInfo::exists(database))
        throw UsageError("--db: '" + database.toStdString() + "' does not exist");
    std::optional<std::int64_t> runId;
    if (parser.isSet(QStringLiteral("run"))) runId = parser.integer(QStringLiteral("run"), 1, 1LL << 53);
    const int point = static_cast<int>(parser.integer(QStringLiteral("point"), 1, core::kMaxControlPoints)) - 1;
    const core::ArmaOrders orders{static_cast<int>(parser.integer(QStringLiteral("ar"), 0, core::kMaxArmaOrder)),
                                  static_cast<int>(parser.integer(QStringLiteral("ma"), 0, core::kMaxArmaOrder))};
    const double gain = parser.number(QStringLiteral("gain"), 0.1, 100.0);

    std::unique_ptr<storage::Database> db;
    std::unique_ptr<storage::SqlHistoryStore> history;
    try {
        db = std::make_unique<storage::Database>(databaseConfigFromOption(database));
        history = std::make_unique<storage::SqlHistoryStore>(*db);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    core::DisturbanceIdentification id;
    try {
        id = core::identifyStoredDisturbance(*history, runId, point, orders, gain);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (parser.json())
        printJson(toJson(id));
    else
        printText(id);
    return kExitOk;
}

}  // namespace

Command makeIdentifyCommand() {
    return {QStringLiteral("identify"),
            QStringLiteral("ARMA model of the part-to-part disturbance of a stored run (prediction-error method), "
                           "offered as the shaping filter"),
            run};
}

}  // namespace tt::cli
