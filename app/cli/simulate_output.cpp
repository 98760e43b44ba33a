#include "app/cli/simulate_output.h"

#include <QJsonArray>
#include <QJsonValue>
#include <cmath>

#include "app/cli/command_parser.h"
#include "app/cli/simulate_checks.h"
#include "app/cli/simulate_verdicts.h"
#include "config/json_eigen.h"

namespace tt::cli {

namespace {

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

/// systematic_from_part and largest_systematic_mm: the closed run's mean true deviation per point after the loop's
/// start-up (each point's in points[].systematic_mm), the largest in magnitude with its sign.
void addSystematicJson(QJsonObject& out, const core::LatheStudyResult& r) {
    if (r.systematicMm.empty()) return;
    double largest = 0.0;
    for (const double v : r.systematicMm)
        if (std::abs(v) > std::abs(largest)) largest = v;
    out.insert(QStringLiteral("systematic_from_part"), static_cast<qint64>(r.systematicFromPart));
    out.insert(QStringLiteral("largest_systematic_mm"), largest);
}

QJsonObject toJson(const core::LatheStudyResult& r, bool profile, const std::optional<QString>& database) {
    QJsonArray points;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        const core::LatheStudyPoint& p = r.points[i];
        QJsonObject point{{QStringLiteral("x_mm"), p.xMm},
                          {QStringLiteral("var_open"), config::finiteOrNull(p.varOpenMm2)},
                          {QStringLiteral("var_closed"), config::finiteOrNull(p.varClosedMm2)},
                          {QStringLiteral("k_eff"), config::finiteOrNull(p.kEff)},
                          {QStringLiteral("k_eff_analytic"), config::finiteOrNull(p.kEffAnalytic)}};
        if (i < r.systematicMm.size()) point.insert(QStringLiteral("systematic_mm"), r.systematicMm[i]);
        points.append(point);
    }
    QJsonObject out{{QStringLiteral("controller"), QString::fromStdString(core::controllerKindName(r.controller))},
                    {QStringLiteral("delay"), r.delay},
                    {QStringLiteral("parts"), static_cast<qint64>(r.parts)},
                    {QStringLiteral("points"), points},
                    {QStringLiteral("k_eff"), config::finiteOrNull(r.kEff)}};
    if (r.ewmaWeight) out.insert(QStringLiteral("ewma_weight"), *r.ewmaWeight);
    out.insert(QStringLiteral("warmup_parts"), static_cast<qint64>(r.warmupParts));
    out.insert(QStringLiteral("verdicts"), verdictsJson(r));
    out.insert(QStringLiteral("tolerance_alarms"), static_cast<qint64>(r.toleranceAlarms));
    addSystematicJson(out, r);
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
    printLine(verdictsText(r));
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

QString alarmKindJson(const std::string& kind) {
    return QString::fromStdString(kind).replace(QLatin1Char('-'), QLatin1Char('_'));
}

/// step:{at_part, size_mm, point, from_part, to_part, residual_pct}, alarms:[{part, kind, point, test,
/// statistic, limit, window_parts, held, message}] and the settings of the plant and the controller.
void addRobustJson(QJsonObject& out, const core::LatheStudyResult& r, const config::LoopScenario& scenario) {
    const core::PlantMismatch& m = scenario.plantMismatch;
    QJsonObject plant{{QStringLiteral("gain_factor"), m.gainFactor},
                      {QStringLiteral("delay"), m.delayParts.value_or(scenario.delay())}};
    // The statistical plant only: the analytic k_eff of the LQG designed for the plant as simulated.
    if (!scenario.lathe) plant.insert(QStringLiteral("lqg_k_eff_analytic"), config::finiteOrNull(r.kEffTruePlantLqg));
    out.insert(QStringLiteral("plant"), plant);
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
                                  {QStringLiteral("test"), a.notice.reference == 1.0   ? QStringLiteral("correlation")
                                                           : a.notice.reference == 2.0 ? QStringLiteral("independence")
                                                                                       : QStringLiteral("variance")},
                                  {QStringLiteral("statistic"), config::finiteOrNull(a.notice.value)},
                                  {QStringLiteral("limit"), config::finiteOrNull(a.notice.limit)},
                                  {QStringLiteral("window_parts"), static_cast<qint64>(a.notice.otherPart)},
                                  {QStringLiteral("held"), a.notice.cause == "hold"},
                                  {QStringLiteral("message"), QString::fromStdString(core::describe(a.notice))}});
    out.insert(QStringLiteral("alarms"), alarms);
    out.insert(QStringLiteral("corrections"), correctionsJson(r, scenario.control.limits));
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

}  // namespace

QJsonObject simulateJson(const core::LatheStudyResult& result, const config::LoopScenario& scenario, bool profile,
                         const std::optional<QString>& database) {
    QJsonObject out = toJson(result, profile, database);
    addRobustJson(out, result, scenario);
    return out;
}

void printSimulateText(const QString& preset, const core::LatheStudyResult& result, std::uint64_t seed, bool profile) {
    printText(preset, result, seed, profile);
    printRobustText(result);
}

}  // namespace tt::cli
