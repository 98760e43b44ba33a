// `trueturn tune`: argument parsing and output only. The plant is identified from the stored run and the LQG
// designed for it by core::tuneFromStoredRun (core/run/stored_run_tuning.h); the scenario comes from
// config::loadLoopScenario; the preset written carries the identified model as its "controller_model" section
// (config/controller_model_config.h).
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cmath>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/controller_model_config.h"
#include "config/json_eigen.h"
#include "config/loop_scenario.h"
#include "core/run/stored_run_tuning.h"
#include "core/storage/adaptation_json.h"
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

QJsonArray numbers(const Eigen::VectorXd& values) {
    return numbers(std::vector<double>(values.data(), values.data() + values.size()));
}

QJsonObject identificationJson(const core::StoredRunTuning& t) {
    const core::PlantIdentification& id = t.identification;
    QJsonArray points;
    for (const core::PointPlantFit& p : id.points)
        points.append(QJsonObject{
            {QStringLiteral("point"), p.point + 1},
            {QStringLiteral("gain"), p.fit.gain},
            {QStringLiteral("gain_std_error"), p.fit.gainStdErr},
            {QStringLiteral("orders"),
             QJsonObject{{QStringLiteral("ar"), p.orders.ar}, {QStringLiteral("ma"), p.orders.ma}}},
            {QStringLiteral("ar"), numbers(p.fit.noise.ar)},
            {QStringLiteral("ma"), numbers(p.fit.noise.ma)},
            {QStringLiteral("ar_std_error"), numbers(p.fit.noise.arStdErr)},
            {QStringLiteral("ma_std_error"), numbers(p.fit.noise.maStdErr)},
            {QStringLiteral("noise_variance"), p.fit.noise.noiseVarianceMm2},
            {QStringLiteral("mean_mm"), p.fit.meanMm},
            {QStringLiteral("ljung_box_p"), config::finiteOrNull(p.fit.noise.ljungBoxP)},
            {QStringLiteral("gain_std_error_joint"), config::finiteOrNull(p.fit.gainStdErrJoint)},
            {QStringLiteral("disturbance_kept"), p.disturbanceKept},
            {QStringLiteral("criterion"), p.criterion},
            {QStringLiteral("parts"), QJsonObject{{QStringLiteral("from"), static_cast<qint64>(p.firstPart)},
                                                  {QStringLiteral("to"), static_cast<qint64>(p.lastPart)}}}});
    return QJsonObject{{QStringLiteral("delay"), id.delayParts()},
                       {QStringLiteral("lag"), id.lagParts},
                       {QStringLiteral("criterion"), QString::fromLatin1(core::informationCriterionName(id.criterion))},
                       {QStringLiteral("lag_scores"), numbers(id.lagScores)},
                       {QStringLiteral("delay_evidence"), config::finiteOrNull(id.delayEvidence)},
                       {QStringLiteral("points"), points},
                       {QStringLiteral("model"), storage::plantModelJson(t.model)}};
}

QJsonObject keffJson(const core::SteadyStateVariances& v) {
    if (!v.available) return QJsonObject{{QStringLiteral("overall"), QJsonValue()}};
    return QJsonObject{{QStringLiteral("overall"), config::finiteOrNull(v.kEffOverall)},
                       {QStringLiteral("points"), numbers(v.kEff)}};
}

QJsonObject toJson(const core::StoredRunTuning& t, const QString& preset, int delay,
                   const std::optional<QString>& out) {
    const core::AdaptedDesign& d = t.design;
    QJsonObject o{{QStringLiteral("run_id"), static_cast<qint64>(t.runId)},
                  {QStringLiteral("preset"), preset},
                  {QStringLiteral("loop_delay"), delay},
                  {QStringLiteral("parts"), QJsonObject{{QStringLiteral("from"), static_cast<qint64>(t.firstPart)},
                                                        {QStringLiteral("to"), static_cast<qint64>(t.lastPart)}}},
                  {QStringLiteral("identification"), identificationJson(t)},
                  {QStringLiteral("design"), QJsonObject{{QStringLiteral("passes"), d.passes},
                                                         {QStringLiteral("why"), QString::fromStdString(d.why)},
                                                         {QStringLiteral("r2_factor"), d.r2Factor},
                                                         {QStringLiteral("required_gain_factor"), d.requiredGainFactor},
                                                         {QStringLiteral("margins"), storage::marginsJson(d.worst)}}},
                  {QStringLiteral("k_eff_on_identified_plant"),
                   QJsonObject{{QStringLiteral("run_controller"), keffJson(t.current)},
                               {QStringLiteral("new_design"), keffJson(t.adapted)},
                               {QStringLiteral("best_ewma"), keffJson(t.ewma)},
                               {QStringLiteral("ewma_weight"), t.ewmaWeight}}}};
    o.insert(QStringLiteral("out"), out ? QJsonValue(*out) : QJsonValue());
    return o;
}

void printText(const core::StoredRunTuning& t) {
    const core::PlantIdentification& id = t.identification;
    printLine(QStringLiteral("Run %1, parts %2 .. %3: plant delay %4 parts (lag %5), chosen by %6 (evidence %7)")
                  .arg(t.runId)
                  .arg(t.firstPart)
                  .arg(t.lastPart)
                  .arg(id.delayParts())
                  .arg(id.lagParts)
                  .arg(QString::fromLatin1(core::informationCriterionName(id.criterion)).toUpper())
                  .arg(id.delayEvidence, 0, 'g', 3));
    for (const core::PointPlantFit& p : id.points) {
        // A kept disturbance has no standard errors of its own (it was not re-estimated).
        auto list = [](const std::vector<double>& values, const std::vector<double>& errors) {
            QStringList out;
            for (std::size_t i = 0; i < values.size(); ++i)
                out << (i < errors.size()
                            ? QStringLiteral("%1 ± %2").arg(values[i], 0, 'f', 3).arg(errors[i], 0, 'f', 3)
                            : QString::number(values[i], 'f', 3));
            return out.join(QStringLiteral(", "));
        };
        printLine(QStringLiteral("point %1: gain %2 ± %3, ARMA(%4,%5) AR [%6] MA [%7], σ² %8 mm²%9")
                      .arg(p.point + 1)
                      .arg(p.fit.gain, 0, 'f', 3)
                      .arg(p.fit.gainStdErr, 0, 'f', 3)
                      .arg(p.orders.ar)
                      .arg(p.orders.ma)
                      .arg(list(p.fit.noise.ar, p.fit.noise.arStdErr), list(p.fit.noise.ma, p.fit.noise.maStdErr))
                      .arg(p.fit.noise.noiseVarianceMm2, 0, 'g', 3)
                      .arg(p.disturbanceKept ? QStringLiteral(" (the run's disturbance model kept)") : QString()));
    }
    const core::AdaptedDesign& d = t.design;
    printLine(d.passes ? QStringLiteral("design: margins hold (gain margin %1, %2 extra part(s) of delay); R2 x %3")
                             .arg(d.worst.gain, 0, 'g', 3)
                             .arg(d.worst.extraPartsTolerated)
                             .arg(d.r2Factor, 0, 'g', 3)
                       : QStringLiteral("design refused: %1").arg(QString::fromStdString(d.why)));
    printLine(
        QStringLiteral("k_eff on the identified plant: run's controller %1, new design %2, best EWMA %3 (weight %4)")
            .arg(t.current.kEffOverall, 0, 'f', 2)
            .arg(t.adapted.kEffOverall, 0, 'f', 2)
            .arg(t.ewma.kEffOverall, 0, 'f', 2)
            .arg(t.ewmaWeight, 0, 'f', 2));
}

/// The preset the next runs use: the run's preset with the identified model, the run's delay and (when the
/// margins needed it) the raised correction weights.
QJsonObject tunedPreset(const config::LoopScenario& scenario, const core::StoredRunTuning& t, const QString& name,
                        const QString& database) {
    QJsonObject plant = scenario.json.value(QStringLiteral("plant")).toObject();
    plant.insert(QStringLiteral("delay"), scenario.delay());
    QJsonObject controller = scenario.json.value(QStringLiteral("controller")).toObject();
    const Eigen::VectorXd r2 = t.design.setup.weights.R2.diagonal();
    controller.insert(QStringLiteral("correction_weight"), numbers(r2));
    return QJsonObject{
        {QStringLiteral("name"), name},
        {QStringLiteral("description"),
         QStringLiteral("The controller of preset %1 designed for the plant identified from %2 of %3 by `trueturn "
                        "tune` (prediction-error method, ARMA orders and plant delay by the %4; the margins of the "
                        "design cover the identified gains' uncertainty). The simulator keeps the preset's plant; the "
                        "controllers use controller_model.")
             .arg(scenario.preset, QString::fromStdString(t.model.source), database,
                  QString::fromStdString(t.model.criterion).toUpper())},
        {QStringLiteral("based_on"), scenario.preset},
        {QStringLiteral("plant"), plant},
        {QStringLiteral("controller"), controller},
        {QStringLiteral("controller_model"), config::controllerModelJson(t.model)}};
}

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("tune"),
        QStringLiteral("Identifies the plant of a stored run from its corrections and measurements (per control point "
                       "the gain and the disturbance as ARMA(p, q), p, q <= 2, by the prediction-error method with "
                       "standard errors; one plant delay; orders and delay by an information criterion), designs the "
                       "LQG for it with its margins checked, and writes a preset that the next runs use."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The history: an SQLite file or postgresql://user@host:port/database."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("run"), QStringLiteral("The stored run's id."), QStringLiteral("N"));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("The run's preset when it is not the one stored with the run (name or JSON file)."),
                     QStringLiteral("name"));
    parser.addOption(QStringLiteral("last"),
                     QStringLiteral("Identify from the last N parts only, 150..10000000 (default: every part)."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("criterion"),
                     QStringLiteral("The information criterion: bic or aic (default: the preset's, bic)."),
                     QStringLiteral("bic|aic"));
    parser.addOption(QStringLiteral("out"), QStringLiteral("Write the tuned preset to this JSON file."),
                     QStringLiteral("set-up.json"));
    parser.parse(arguments);

    const QString database = parser.required(QStringLiteral("db"));
    if (!isPostgresOption(database) && !QFileInfo::exists(database))
        throw UsageError("--db: '" + database.toStdString() + "' does not exist");
    if (!parser.isSet(QStringLiteral("run"))) throw UsageError("--run: give the stored run to tune from");
    const std::int64_t runId = parser.integer(QStringLiteral("run"), 1, 1LL << 53);
    std::optional<std::int64_t> last;
    if (parser.isSet(QStringLiteral("last"))) last = parser.integer(QStringLiteral("last"), 150, 10000000);

    std::unique_ptr<storage::Database> db;
    std::unique_ptr<storage::SqlHistoryStore> history;
    try {
        db = std::make_unique<storage::Database>(databaseConfigFromOption(database));
        history = std::make_unique<storage::SqlHistoryStore>(*db);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    std::optional<core::RunSummary> summary;
    for (const core::RunSummary& r : history->runs())
        if (r.runId == runId) summary = r;
    if (!summary) throw UsageError("--run: the history has no run " + std::to_string(runId));
    const QString preset = parser.isSet(QStringLiteral("preset")) ? parser.value(QStringLiteral("preset"))
                                                                  : QString::fromStdString(summary->description.preset);
    config::LoopScenario scenario;
    try {
        scenario = config::loadLoopScenario(preset, summary->description.delayParts);
    } catch (const std::invalid_argument& e) {
        throw UsageError("the run's preset '" + preset.toStdString() + "' cannot be read (" + e.what() +
                         "); give it with --preset");
    }
    if (parser.isSet(QStringLiteral("criterion")))
        scenario.adaptation.criterion = core::informationCriterionFromName(
            parser.choice(QStringLiteral("criterion"), {QStringLiteral("bic"), QStringLiteral("aic")}).toStdString());
    core::StoredRunTuning t;
    try {
        t = core::tuneFromStoredRun(*history, runId, scenario.control, scenario.adaptation, last);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("run ") + std::to_string(runId) + ": " + e.what());
    }
    std::optional<QString> out;
    if (parser.isSet(QStringLiteral("out")) && t.design.passes) {
        out = parser.value(QStringLiteral("out"));
        const QJsonObject tuned = tunedPreset(scenario, t, QFileInfo(*out).completeBaseName(), database);
        writeOutputFile(*out, QJsonDocument(tuned).toJson(QJsonDocument::Indented));
    }
    if (parser.json())
        printJson(toJson(t, preset, scenario.delay(), out));
    else
        printText(t);
    if (!t.design.passes)
        throw std::runtime_error("the design for the identified plant fails its margins, no preset written: " +
                                 t.design.why);
    return kExitOk;
}

}  // namespace

Command makeTuneCommand() {
    return {QStringLiteral("tune"),
            QStringLiteral("Identifies the plant of a stored run (gain, delay, ARMA disturbance) and designs the LQG "
                           "for it; writes the preset the next runs use"),
            run};
}

}  // namespace tt::cli
