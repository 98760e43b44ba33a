// `trueturn simulate`: argument parsing and output only. The work is in core: the scenario comes from
// config::loadRunToRunSetup, the study (controller choice, EWMA weight grid, Monte-Carlo on the
// statistical plant, closed-loop Lyapunov analysis) from core::runRunToRunStudy
// (core/sim/run_to_run_study.h); per-part steps are StochasticPlant::machine/draw and the
// RunToRunController interface.
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <cmath>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "config/plant_config.h"
#include "core/control/run_to_run_plant.h"
#include "core/sim/run_to_run_study.h"

namespace tt::cli {

namespace {

QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

QJsonObject toJson(const core::StudyResult& r) {
    QJsonArray points;
    for (const core::StudyPoint& p : r.points)
        points.append(QJsonObject{{QStringLiteral("x_mm"), p.xMm},
                                  {QStringLiteral("var_open"), finiteOrNull(p.varOpenMm2)},
                                  {QStringLiteral("var_closed"), finiteOrNull(p.varClosedMm2)},
                                  {QStringLiteral("k_eff"), finiteOrNull(p.kEff)},
                                  {QStringLiteral("k_eff_analytic"), finiteOrNull(p.kEffAnalytic)}});
    QJsonObject out{{QStringLiteral("controller"), QString::fromStdString(core::controllerKindName(r.controller))},
                    {QStringLiteral("delay"), r.delay},
                    {QStringLiteral("parts"), static_cast<qint64>(r.parts)},
                    {QStringLiteral("points"), points},
                    {QStringLiteral("k_eff"), finiteOrNull(r.kEff)}};
    if (r.ewmaWeight) out.insert(QStringLiteral("ewma_weight"), *r.ewmaWeight);
    return out;
}

QString g(double v, int precision = 4) {
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QStringLiteral("n/a");
}

void printText(const QString& preset, const core::StudyResult& r, std::uint64_t seed) {
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
    for (const core::StudyPoint& p : r.points)
        printLine(QStringLiteral("%1 %2 %3 %4 %5")
                      .arg(p.xMm, 8, 'f', 1)
                      .arg(g(p.varOpenMm2), 13)
                      .arg(g(p.varClosedMm2), 15)
                      .arg(g(p.kEff, 3), 7)
                      .arg(g(p.kEffAnalytic, 3), 9));
    printLine(QStringLiteral("k_eff (all points): %1 simulated, %2 analytic; %3 measured value(s) rejected")
                  .arg(g(r.kEff, 3), g(r.kEffAnalytic, 3))
                  .arg(r.rejectedValues));
}

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("simulate"),
                         QStringLiteral("Monte-Carlo run-to-run simulation of a scenario preset (paper 000, Table 2): "
                                        "open and closed loop on the same disturbance, k_eff per control point, "
                                        "simulated and analytic."));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("Scenario preset name or JSON file (default paper-2012)."), QStringLiteral("name"),
                     QStringLiteral("paper-2012"));
    parser.addOption(QStringLiteral("delay"),
                     QStringLiteral("Transport delay z in parts, 1..8 (default: the preset's)."), QStringLiteral("z"));
    parser.addOption(QStringLiteral("parts"), QStringLiteral("Parts to simulate, 100..10000000 (default 20000)."),
                     QStringLiteral("n"), QStringLiteral("20000"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Random seed, 0..2^53 (default 1)."), QStringLiteral("s"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("controller"), QStringLiteral("lqg, ewma or open (default lqg)."),
                     QStringLiteral("kind"), QStringLiteral("lqg"));
    parser.addOption(QStringLiteral("ewma-weight"),
                     QStringLiteral("EWMA weight in (0, 1], or auto: the best on a grid 0.05..1 (default: the "
                                    "preset's)."),
                     QStringLiteral("w"));
    parser.parse(arguments);

    std::optional<int> delay;
    if (parser.isSet(QStringLiteral("delay")))
        delay = static_cast<int>(parser.integer(QStringLiteral("delay"), 1, core::kMaxDelay));
    core::StudyOptions options;
    options.monteCarlo.parts = parser.integer(QStringLiteral("parts"), 100, 10000000);
    options.monteCarlo.seed = static_cast<std::uint64_t>(parser.integer(QStringLiteral("seed"), 0, 1LL << 53));
    options.controller = core::controllerKindFromName(
        parser
            .choice(QStringLiteral("controller"),
                    {QStringLiteral("lqg"), QStringLiteral("ewma"), QStringLiteral("open")})
            .toStdString());
    const QString preset = parser.value(QStringLiteral("preset"));
    core::RunToRunSetup setup = config::loadRunToRunSetup(preset, delay);
    if (parser.isSet(QStringLiteral("ewma-weight"))) {
        if (options.controller != core::ControllerKind::Ewma)
            throw UsageError("--ewma-weight: only with --controller ewma");
        if (parser.value(QStringLiteral("ewma-weight")) == QLatin1String("auto")) {
            setup.ewmaWeightAuto = true;
        } else {
            const double w = parser.number(QStringLiteral("ewma-weight"), 0.0, 1.0);
            if (w <= 0.0) throw UsageError("--ewma-weight: must be in (0, 1] or auto");
            options.ewmaWeight = w;
        }
    }
    const core::StudyResult result = core::runRunToRunStudy(setup, options);
    if (parser.json())
        printJson(toJson(result));
    else
        printText(preset, result, options.monteCarlo.seed);
    return kExitOk;
}

}  // namespace

Command makeSimulateCommand() {
    return {QStringLiteral("simulate"),
            QStringLiteral("Monte-Carlo run-to-run simulation: k_eff of LQG, EWMA or open loop (Table 2)"), run};
}

}  // namespace tt::cli
