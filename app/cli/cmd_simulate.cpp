// `trueturn simulate`: argument parsing and output only. The run is assembled by the run builder
// (core/run/shaft_run_builder.h) on the built-in simulated lathe (core::SimulatedLathe: the physical
// lathe of a preset with a "lathe" section, else the controller's statistical plant) and driven by
// core::runLatheStudy (core/run/shaft_study.h); the scenario comes from config::loadLoopScenario; the
// history is storage::SqlHistoryStore.
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <cmath>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "app/cli/run_interrupt.h"
#include "app/cli/simulate_adaptation.h"
#include "app/cli/simulate_checks.h"
#include "config/json_eigen.h"
#include "config/loop_scenario.h"
#include "core/control/run_to_run_plant.h"
#include "core/loop/mismatch_monitor.h"
#include "core/run/shaft_study.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"

namespace tt::cli {

namespace {

/// What the run is made of; stored with a --db run so --resume sets it up again.
struct RunChoice {
    QString preset = QStringLiteral("paper-2012");
    std::optional<int> delay;
    std::int64_t parts = 20000;
    std::int64_t warmup = 100;
    std::uint64_t seed = 1;
    core::ControllerKind controller = core::ControllerKind::Lqg;
    std::optional<double> ewmaWeight;  ///< none: the preset's (auto: best on the grid)
    bool ewmaAuto = false;

    QJsonObject toJson(int delayUsed) const {
        QJsonObject o{{QStringLiteral("source"), QStringLiteral("simulate")},
                      {QStringLiteral("preset"), preset},
                      {QStringLiteral("delay"), delayUsed},
                      {QStringLiteral("parts"), static_cast<qint64>(parts)},
                      {QStringLiteral("warmup"), static_cast<qint64>(warmup)},
                      {QStringLiteral("seed"), static_cast<qint64>(seed)},
                      {QStringLiteral("controller"), QString::fromStdString(core::controllerKindName(controller))}};
        if (ewmaWeight) o.insert(QStringLiteral("ewma_weight"), *ewmaWeight);
        if (ewmaAuto) o.insert(QStringLiteral("ewma_weight"), QStringLiteral("auto"));
        return o;
    }

    static RunChoice fromJson(const QJsonObject& o) {
        RunChoice c;
        if (o.value(QStringLiteral("source")).toString() != QLatin1String("simulate"))
            throw UsageError("--resume: the run was not started by 'trueturn simulate'");
        c.preset = o.value(QStringLiteral("preset")).toString();
        c.delay = o.value(QStringLiteral("delay")).toInt();
        c.parts = o.value(QStringLiteral("parts")).toInteger();
        c.warmup = o.value(QStringLiteral("warmup")).toInteger();
        c.seed = static_cast<std::uint64_t>(o.value(QStringLiteral("seed")).toInteger());
        c.controller = core::controllerKindFromName(o.value(QStringLiteral("controller")).toString().toStdString());
        const QJsonValue w = o.value(QStringLiteral("ewma_weight"));
        if (w.isDouble()) c.ewmaWeight = w.toDouble();
        c.ewmaAuto = w.isString();
        if (c.preset.isEmpty() || c.parts < 1 || c.warmup < 0)
            throw UsageError("--resume: the stored settings of the run are damaged");
        checkStoredParts(c.parts, c.warmup);
        return c;
    }
};

QString g(double v, int precision = 4) {
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QStringLiteral("n/a");
}

/// The largest |mean| of the profile and where.
std::pair<double, double> profilePeak(const core::LatheStudyResult& r) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < r.profileMeanMm.size(); ++i)
        if (std::abs(r.profileMeanMm[i]) > std::abs(r.profileMeanMm[best])) best = i;
    return {r.profileZMm.at(best), r.profileMeanMm.at(best)};
}

QJsonObject toJson(const core::LatheStudyResult& r, bool profile, const std::optional<QString>& database) {
    QJsonArray points;
    for (const core::LatheStudyPoint& p : r.points)
        points.append(QJsonObject{{QStringLiteral("x_mm"), p.xMm},
                                  {QStringLiteral("var_open"), config::finiteOrNull(p.varOpenMm2)},
                                  {QStringLiteral("var_closed"), config::finiteOrNull(p.varClosedMm2)},
                                  {QStringLiteral("k_eff"), config::finiteOrNull(p.kEff)},
                                  {QStringLiteral("k_eff_analytic"), config::finiteOrNull(p.kEffAnalytic)}});
    QJsonObject out{{QStringLiteral("controller"), QString::fromStdString(core::controllerKindName(r.controller))},
                    {QStringLiteral("delay"), r.delay},
                    {QStringLiteral("parts"), static_cast<qint64>(r.parts)},
                    {QStringLiteral("points"), points},
                    {QStringLiteral("k_eff"), config::finiteOrNull(r.kEff)}};
    if (r.ewmaWeight) out.insert(QStringLiteral("ewma_weight"), *r.ewmaWeight);
    out.insert(QStringLiteral("verdicts"),
               QJsonObject{{QStringLiteral("good"), static_cast<qint64>(r.verdicts.good)},
                           {QStringLiteral("rework"), static_cast<qint64>(r.verdicts.rework)},
                           {QStringLiteral("scrap"), static_cast<qint64>(r.verdicts.scrap)}});
    out.insert(QStringLiteral("tolerance_alarms"), static_cast<qint64>(r.toleranceAlarms));
    if (profile) {
        QJsonArray rows;
        for (std::size_t i = 0; i < r.profileZMm.size(); ++i)
            rows.append(QJsonObject{{QStringLiteral("x_mm"), r.profileZMm[i]},
                                    {QStringLiteral("mean_error_mm"), r.profileMeanMm[i]},
                                    {QStringLiteral("std_error_mm"), r.profileStdMm[i]}});
        out.insert(QStringLiteral("profile"), rows);
        out.insert(QStringLiteral("profile_parts"),
                   QJsonObject{{QStringLiteral("from"), static_cast<qint64>(r.profileFromPart)},
                               {QStringLiteral("to"), static_cast<qint64>(r.profileToPart)}});
        const auto [x, value] = profilePeak(r);
        out.insert(QStringLiteral("profile_peak"),
                   QJsonObject{{QStringLiteral("x_mm"), x}, {QStringLiteral("mean_error_mm"), value}});
    }
    if (database) {
        out.insert(QStringLiteral("database"), *database);
        out.insert(QStringLiteral("run_id"), r.runId ? QJsonValue(static_cast<qint64>(*r.runId)) : QJsonValue());
    }
    return out;
}

void printText(const QString& preset, const core::LatheStudyResult& r, std::uint64_t seed, bool profile) {
    QString controller = QString::fromStdString(core::controllerKindName(r.controller));
    if (r.ewmaWeight) controller += QStringLiteral(" (weight %1)").arg(g(*r.ewmaWeight, 3));
    printLine(QStringLiteral("Run-to-run simulation, preset %1: controller %2, delay z = %3, %4 parts, seed %5")
                  .arg(preset, controller)
                  .arg(r.delay)
                  .arg(r.parts)
                  .arg(seed));
    printLine(QStringLiteral("%1 %2 %3 %4 %5")
                  .arg(QStringLiteral("x, mm"), 8)
                  .arg(QStringLiteral("open σ², mm²"), 13)
                  .arg(QStringLiteral("closed σ², mm²"), 15)
                  .arg(QStringLiteral("k_eff"), 7)
                  .arg(QStringLiteral("analytic"), 9));
    for (const core::LatheStudyPoint& p : r.points)
        printLine(QStringLiteral("%1 %2 %3 %4 %5")
                      .arg(p.xMm, 8, 'f', 1)
                      .arg(g(p.varOpenMm2), 13)
                      .arg(g(p.varClosedMm2), 15)
                      .arg(g(p.kEff, 3), 7)
                      .arg(g(p.kEffAnalytic, 3), 9));
    printLine(QStringLiteral("k_eff (all points): %1 simulated, %2 analytic; %3 measured value(s) rejected")
                  .arg(g(r.kEff, 3), g(r.kEffAnalytic, 3))
                  .arg(r.rejectedValues));
    if (!std::isfinite(r.kEff)) printLine(kEffUndefinedNote());
    printLine(QStringLiteral("verdicts: %1 good, %2 rework, %3 scrap; %4 out-of-tolerance alarm(s)")
                  .arg(r.verdicts.good)
                  .arg(r.verdicts.rework)
                  .arg(r.verdicts.scrap)
                  .arg(r.toleranceAlarms));
    if (!profile) return;
    printLine(
        QStringLiteral("Profile of parts %1 .. %2 (true diameter error):").arg(r.profileFromPart).arg(r.profileToPart));
    printLine(QStringLiteral("%1 %2 %3")
                  .arg(QStringLiteral("x, mm"), 8)
                  .arg(QStringLiteral("mean, mm"), 10)
                  .arg(QStringLiteral("σ, mm"), 9));
    for (std::size_t i = 0; i < r.profileZMm.size(); ++i)
        printLine(QStringLiteral("%1 %2 %3")
                      .arg(r.profileZMm[i], 8, 'f', 1)
                      .arg(r.profileMeanMm[i], 10, 'f', 4)
                      .arg(r.profileStdMm[i], 9, 'f', 4));
    const auto [x, value] = profilePeak(r);
    printLine(QStringLiteral("largest mean error %1 mm at x = %2 mm").arg(value, 0, 'f', 4).arg(x, 0, 'f', 1));
}

// ---- plant mismatch, integral action, mismatch monitor (options and output) ------------------------------

/// --plant-gain, --plant-delay, --step-at, --step-mm, --step-point, --integral, --integral-weight.
void addRobustOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("plant-gain"),
                     QStringLiteral("The simulated plant's gain as a multiple of the model's k_i, 0.1..10 (default 1; "
                                    "statistical plant only)."),
                     QStringLiteral("k"));
    parser.addOption(QStringLiteral("plant-delay"),
                     QStringLiteral("The simulated plant's delay in parts, from the model's z to 8 (default: the "
                                    "model's)."),
                     QStringLiteral("z"));
    parser.addOption(QStringLiteral("step-at"),
                     QStringLiteral("A step in the plant from this part on, 1..10000000 (with --step-mm)."),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("step-mm"), QStringLiteral("Size of the step in diameter, -1..1 mm, not 0."),
                     QStringLiteral("mm"));
    parser.addOption(QStringLiteral("step-point"),
                     QStringLiteral("The step at this control point only, 1..16 (default: the whole part)."),
                     QStringLiteral("i"));
    parser.addOption(QStringLiteral("integral"),
                     QStringLiteral("Integral action of the LQG (an integrating disturbance state): on or off "
                                    "(default: the preset's)."),
                     QStringLiteral("on|off"));
    parser.addOption(QStringLiteral("integral-weight"),
                     QStringLiteral("Step variance of the integrating state as a share of the disturbance "
                                    "variance, 1e-6..1 (default: the preset's, 0.3)."),
                     QStringLiteral("w"));
    parser.addOption(QStringLiteral("drift-weight"),
                     QStringLiteral("Double EWMA: the drift weight lambda2 in (0, 1) (default 0.1; the offset's "
                                    "weight is --ewma-weight)."),
                     QStringLiteral("w"));
}

/// The robustness options given on the command line (a resumed run keeps its own settings).
bool robustOptionsSet(const CommandParser& parser) {
    for (const char* option : {"plant-gain", "plant-delay", "step-at", "step-mm", "step-point", "integral",
                               "integral-weight", "drift-weight"})
        if (parser.isSet(QString::fromLatin1(option))) return true;
    return adaptationOptionsSet(parser);
}

/// Applies the robustness options to the scenario; throws UsageError naming the option.
void applyRobustOptions(const CommandParser& parser, config::LoopScenario& scenario) {
    core::PlantMismatch& m = scenario.plantMismatch;
    if (parser.isSet(QStringLiteral("plant-gain")))
        m.gainFactor =
            parser.number(QStringLiteral("plant-gain"), core::kMinPlantGainFactor, core::kMaxPlantGainFactor);
    if (parser.isSet(QStringLiteral("plant-delay")))
        m.delayParts =
            static_cast<int>(parser.integer(QStringLiteral("plant-delay"), scenario.delay(), core::kMaxDelay));
    if (parser.isSet(QStringLiteral("step-at")) != parser.isSet(QStringLiteral("step-mm")))
        throw UsageError("--step-at and --step-mm: give both (the part and the size of the step)");
    if (parser.isSet(QStringLiteral("step-point")) && !parser.isSet(QStringLiteral("step-at")))
        throw UsageError("--step-point: only with --step-at and --step-mm");
    if (parser.isSet(QStringLiteral("step-at"))) {
        core::PlantStep step;
        step.atPart = parser.integer(QStringLiteral("step-at"), 1, 10000000);
        step.sizeMm = parser.number(QStringLiteral("step-mm"), -core::kMaxPlantStepMm, core::kMaxPlantStepMm);
        if (step.sizeMm == 0.0) throw UsageError("--step-mm: must not be 0");
        if (parser.isSet(QStringLiteral("step-point")))
            step.point =
                static_cast<int>(parser.integer(QStringLiteral("step-point"), 1,
                                                static_cast<long long>(scenario.control.plant.points.size()))) -
                1;
        m.step = step;
    }
    if (parser.isSet(QStringLiteral("integral")))
        scenario.control.integral.enabled =
            parser.choice(QStringLiteral("integral"), {QStringLiteral("on"), QStringLiteral("off")}) ==
            QLatin1String("on");
    if (parser.isSet(QStringLiteral("integral-weight")))
        scenario.control.integral.weight =
            parser.number(QStringLiteral("integral-weight"), core::kMinIntegralWeight, core::kMaxIntegralWeight);
    if (parser.isSet(QStringLiteral("drift-weight"))) {
        if (parser.value(QStringLiteral("controller")) != QLatin1String("dewma"))
            throw UsageError("--drift-weight: only with --controller dewma");
        scenario.control.ewma.driftWeight = parser.number(QStringLiteral("drift-weight"), 0.0, 0.999);
        if (scenario.control.ewma.driftWeight <= 0.0) throw UsageError("--drift-weight: must be in (0, 1)");
    }
    applyAdaptationOptions(parser, scenario);
    try {
        m.validate(scenario.delay(), scenario.control.plant.points.size());
        if (scenario.lathe && (m.gainFactor != 1.0 || (m.step && m.step->point)))
            throw std::invalid_argument(
                "--plant-gain and --step-point: simulated on the statistical plant only (a preset without a lathe "
                "section)");
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

/// The stable kind name of an alarm in JSON ("model-mismatch" -> "model_mismatch").
QString alarmKindJson(const std::string& kind) {
    return QString::fromStdString(kind).replace(QLatin1Char('-'), QLatin1Char('_'));
}

/// step:{at_part, size_mm, point, from_part, to_part, residual_pct}, alarms:[{part, kind, point, test,
/// statistic, limit, window_parts, held, message}] and the settings of the plant and the controller.
void addRobustJson(QJsonObject& out, const core::LatheStudyResult& r, const config::LoopScenario& scenario) {
    const core::PlantMismatch& m = scenario.plantMismatch;
    out.insert(QStringLiteral("plant"),
               QJsonObject{{QStringLiteral("gain_factor"), m.gainFactor},
                           {QStringLiteral("delay"), m.delayParts.value_or(scenario.delay())}});
    out.insert(QStringLiteral("integral"),
               scenario.control.integral.enabled && r.controller == core::ControllerKind::Lqg
                   ? QJsonValue(QJsonObject{{QStringLiteral("weight"), scenario.control.integral.weight}})
                   : QJsonValue(false));
    if (r.step)
        out.insert(QStringLiteral("step"),
                   QJsonObject{{QStringLiteral("at_part"), static_cast<qint64>(r.step->atPart)},
                               {QStringLiteral("size_mm"), r.step->sizeMm},
                               {QStringLiteral("point"), r.step->point ? QJsonValue(*r.step->point + 1) : QJsonValue()},
                               {QStringLiteral("from_part"), static_cast<qint64>(r.step->fromPart)},
                               {QStringLiteral("to_part"), static_cast<qint64>(r.step->toPart)},
                               {QStringLiteral("residual_pct"), config::finiteOrNull(r.step->residualPct)}});
    QJsonArray alarms;
    for (const core::RecordedAlarm& a : r.modelAlarms)
        alarms.append(QJsonObject{{QStringLiteral("part"), static_cast<qint64>(a.part)},
                                  {QStringLiteral("kind"), alarmKindJson(a.kind)},
                                  {QStringLiteral("point"), a.notice.point},
                                  {QStringLiteral("test"), a.notice.reference == 1.0 ? QStringLiteral("correlation")
                                                                                     : QStringLiteral("variance")},
                                  {QStringLiteral("statistic"), config::finiteOrNull(a.notice.value)},
                                  {QStringLiteral("limit"), config::finiteOrNull(a.notice.limit)},
                                  {QStringLiteral("window_parts"), static_cast<qint64>(a.notice.otherPart)},
                                  {QStringLiteral("held"), a.notice.cause == "hold"},
                                  {QStringLiteral("message"), QString::fromStdString(core::describe(a.notice))}});
    out.insert(QStringLiteral("alarms"), alarms);
    out.insert(QStringLiteral("corrections"),
               QJsonObject{{QStringLiteral("max_abs_mm"), r.maxCorrectionMm},
                           {QStringLiteral("max_step_mm"), r.maxCorrectionStepMm},
                           {QStringLiteral("limit_abs_mm"), scenario.control.limits.maxAbsMm},
                           {QStringLiteral("limit_step_mm"), scenario.control.limits.maxStepMm}});
}

/// The step residual and the model alarms in the text output.
void printRobustText(const core::LatheStudyResult& r) {
    if (r.step)
        printLine(QStringLiteral("step of %1 mm at part %2: %3 % of it left over parts %4 .. %5")
                      .arg(r.step->sizeMm)
                      .arg(r.step->atPart)
                      .arg(g(r.step->residualPct, 3))
                      .arg(r.step->fromPart)
                      .arg(r.step->toPart));
    for (const core::RecordedAlarm& a : r.modelAlarms)
        printLine(QStringLiteral("alarm: ") + QString::fromStdString(core::describe(a.notice)));
}

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("simulate"),
                         QStringLiteral("The closed loop on the built-in simulator, headless (paper 000): parts are "
                                        "machined, measured and corrected part by part with the controller; the open "
                                        "loop runs on the same disturbance for k_eff per control point (Table 2). A "
                                        "preset with a lathe section runs the physical lathe, otherwise the "
                                        "controller's statistical plant."));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("Scenario preset name or JSON file (default paper-2012; the physical lathe: "
                                    "paper-2012-group1..3)."),
                     QStringLiteral("name"), QStringLiteral("paper-2012"));
    parser.addOption(QStringLiteral("delay"),
                     QStringLiteral("Transport delay z in parts, 1..8 (default: the preset's)."), QStringLiteral("z"));
    parser.addOption(QStringLiteral("parts"),
                     QStringLiteral("Parts counted in the statistics, 100..10000000 (default 20000)."),
                     QStringLiteral("n"), QStringLiteral("20000"));
    parser.addOption(QStringLiteral("warmup"),
                     QStringLiteral("Parts machined first and not counted, 0..1000000 (default 100)."),
                     QStringLiteral("n"), QStringLiteral("100"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Random seed, 0..2^53 (default 1)."), QStringLiteral("s"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("controller"),
                     QStringLiteral("lqg, ewma, dewma (double EWMA) or open (default lqg)."), QStringLiteral("kind"),
                     QStringLiteral("lqg"));
    parser.addOption(QStringLiteral("ewma-weight"),
                     QStringLiteral("EWMA weight in (0, 1], or auto: the best on a grid 0.05..1 (default: the "
                                    "preset's)."),
                     QStringLiteral("w"));
    parser.addOption(QStringLiteral("profile"),
                     QStringLiteral("Add the profile of the finished parts: mean and standard deviation of the "
                                    "diameter error along the part, after the loop's start-up (2z + 5 parts)."));
    parser.addOption(QStringLiteral("profile-step"),
                     QStringLiteral("Spacing of the profile positions, 1..100 mm (default 12.5: the paper's 25 mm "
                                    "grid and the middle)."),
                     QStringLiteral("mm"), QStringLiteral("12.5"));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("Store the run in this history (each part one transaction): an SQLite file or "
                                    "postgresql://user@host:port/database."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("machine"),
                     QStringLiteral("The lathe's name stored with the run (a plant-wide history holds several)."),
                     QStringLiteral("name"));
    parser.addOption(QStringLiteral("resume"),
                     QStringLiteral("Continue a run stored in --db from its next part, with its own settings and the "
                                    "stored controller state: --resume N continues run N, --resume alone the newest."));
    parser.addOption(QStringLiteral("run"), QStringLiteral("With --resume: the run to continue (as --resume N)."),
                     QStringLiteral("N"));
    addProgressOption(parser);
    parser.addOption(QStringLiteral("speed"),
                     QStringLiteral("Simulated time per wall time: 0 (the default: as fast as possible) or 1..1e9 "
                                    "(1: the lathe's own pace; 360: a 6-minute part per second)."),
                     QStringLiteral("x"), QStringLiteral("0"));
    addRobustOptions(parser);
    addAdaptationOptions(parser);
    parser.parse(splitResumeRun(arguments));

    const bool resume = parser.isSet(QStringLiteral("resume"));
    const std::optional<QString> database =
        parser.isSet(QStringLiteral("db")) ? std::optional<QString>(parser.value(QStringLiteral("db"))) : std::nullopt;
    if (resume && !database) throw UsageError("--resume: needs --db, the history of the run to continue");
    const double speed = simulationSpeed(parser);
    const std::optional<std::int64_t> resumeRun = resumeRunId(parser);
    const double profileStep = parser.number(QStringLiteral("profile-step"), 1.0, 100.0);

    std::unique_ptr<storage::Database> db;
    std::unique_ptr<storage::SqlHistoryStore> history;
    if (database) {
        if (resume && !isPostgresOption(*database) && !QFileInfo::exists(*database))
            throw UsageError("--db: '" + database->toStdString() + "' does not exist, so there is nothing to resume");
        try {
            db = std::make_unique<storage::Database>(databaseConfigFromOption(*database));
            history = std::make_unique<storage::SqlHistoryStore>(*db);
        } catch (const storage::StorageError& e) {
            throw UsageError(std::string("--db: ") + e.what());
        }
    }

    RunChoice choice;
    std::optional<core::ResumePoint> resumePoint;
    if (resume) {
        for (const char* option : {"preset", "delay", "parts", "warmup", "seed", "controller", "ewma-weight"})
            if (parser.isSet(QString::fromLatin1(option)))
                throw UsageError(std::string("--") + option +
                                 ": a resumed run keeps its own settings; leave the option out");
        if (robustOptionsSet(parser))
            throw UsageError(
                "--resume: a resumed run keeps its own plant and controller; leave the plant, step, "
                "integral and mismatch options out");
        resumePoint = findResumePoint(*history, resumeRun);
        const QJsonObject stored =
            QJsonDocument::fromJson(QByteArray::fromStdString(resumePoint->run.description.settingsJson)).object();
        choice = RunChoice::fromJson(stored);
    } else {
        if (parser.isSet(QStringLiteral("delay")))
            choice.delay = static_cast<int>(parser.integer(QStringLiteral("delay"), 1, core::kMaxDelay));
        choice.parts = parser.integer(QStringLiteral("parts"), 100, 10000000);
        choice.warmup = parser.integer(QStringLiteral("warmup"), 0, 1000000);
        choice.seed = static_cast<std::uint64_t>(parser.integer(QStringLiteral("seed"), 0, 1LL << 53));
        choice.controller = core::controllerKindFromName(
            parser
                .choice(QStringLiteral("controller"), {QStringLiteral("lqg"), QStringLiteral("ewma"),
                                                       QStringLiteral("open"), QStringLiteral("dewma")})
                .toStdString());
        choice.preset = parser.value(QStringLiteral("preset"));
        if (parser.isSet(QStringLiteral("ewma-weight"))) {
            if (choice.controller != core::ControllerKind::Ewma && choice.controller != core::ControllerKind::Dewma)
                throw UsageError("--ewma-weight: only with --controller ewma or dewma");
            if (parser.value(QStringLiteral("ewma-weight")) == QLatin1String("auto")) {
                choice.ewmaAuto = true;
            } else {
                const double w = parser.number(QStringLiteral("ewma-weight"), 0.0, 1.0);
                if (w <= 0.0) throw UsageError("--ewma-weight: must be in (0, 1] or auto");
                choice.ewmaWeight = w;
            }
        }
    }

    config::LoopScenario scenario = config::loadLoopScenario(choice.preset, choice.delay);
    if (choice.ewmaAuto) scenario.control.ewmaWeightAuto = true;
    if (!resume) applyRobustOptions(parser, scenario);
    core::LatheStudyOptions options;
    options.controller = choice.controller;
    options.ewmaWeight = choice.ewmaWeight;
    options.parts = choice.parts;
    options.warmupParts = choice.warmup;
    options.speed = speed;
    if (parser.isSet(QStringLiteral("profile"))) {
        const double length = scenario.partLengthMm;
        const int steps = static_cast<int>(std::floor(length / profileStep + 1e-9));
        for (int i = 0; i <= steps; ++i)
            options.profileZMm.push_back(std::min(length, i * profileStep));
        if (options.profileZMm.back() < length - 1e-9) options.profileZMm.push_back(length);
    }
    options.history = history.get();
    options.resume = resumePoint;
    options.description = {choice.preset.toStdString(),
                           core::controllerKindName(choice.controller),
                           scenario.delay(),
                           scenario.nominalDiameterMm,
                           scenario.partLengthMm,
                           scenario.loopConfig(false, std::nullopt).pointZMm,
                           QJsonDocument(choice.toJson(scenario.delay())).toJson(QJsonDocument::Compact).toStdString()};

    options.description.machine = parser.value(QStringLiteral("machine")).toStdString();

    // A run that stops early (a fault, a history that cannot be written) is a std::runtime_error: exit 1
    // with the reason; what was stored stays stored and the run can be resumed.
    // Ctrl-C or SIGTERM: the run stops after its current part, everything stored is committed, exit 130.
    const std::optional<core::LatheStudyResult> study = runStudyUntilStopped(
        scenario, choice.seed, options, parser.isSet(QStringLiteral("progress")), database.value_or(QString()));
    if (!study) return kExitInterrupted;
    const core::LatheStudyResult& result = *study;
    if (parser.json()) {
        QJsonObject out = toJson(result, parser.isSet(QStringLiteral("profile")), database);
        addRobustJson(out, result, scenario);
        addAdaptationJson(out, result, scenario);
        printJson(out);
    } else {
        printText(choice.preset, result, choice.seed, parser.isSet(QStringLiteral("profile")));
        printRobustText(result);
        printAdaptationText(result);
    }
    return kExitOk;
}

}  // namespace

Command makeSimulateCommand() {
    return {QStringLiteral("simulate"),
            QStringLiteral("The closed loop on the built-in simulator: k_eff of LQG, EWMA or open loop (Table 2), "
                           "the profile of the parts, a stored and resumable run"),
            run};
}

}  // namespace tt::cli
