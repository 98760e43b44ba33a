#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "config/plant_config.h"
#include "core/control/lqg_design.h"
#include "core/control/run_to_run_plant.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::cli {

namespace {

const QString kDefaultPreset = QStringLiteral("paper-2012");

QJsonObject toJson(const core::RunToRunPlant& plant, const core::LqgWeights& w, const core::LqgDesign& d) {
    QJsonArray points;
    for (double x : plant.xMm)
        points.append(QJsonObject{{QStringLiteral("x_mm"), x}});
    using config::matrixToJson;
    return QJsonObject{
        {QStringLiteral("delay"), plant.delay},
        {QStringLiteral("points"), points},
        {QStringLiteral("plant"), QJsonObject{{QStringLiteral("A"), matrixToJson(plant.A)},
                                              {QStringLiteral("B"), matrixToJson(plant.B)},
                                              {QStringLiteral("C"), matrixToJson(plant.C)},
                                              {QStringLiteral("D"), matrixToJson(plant.D)},
                                              {QStringLiteral("G"), matrixToJson(plant.G)}}},
        {QStringLiteral("noise"),
         QJsonObject{{QStringLiteral("W"), matrixToJson(plant.W)}, {QStringLiteral("V"), matrixToJson(plant.V)}}},
        {QStringLiteral("weights"),
         QJsonObject{{QStringLiteral("R1"), matrixToJson(w.R1)}, {QStringLiteral("R2"), matrixToJson(w.R2)}}},
        {QStringLiteral("lq"), QJsonObject{{QStringLiteral("K"), matrixToJson(d.K)}}},
        {QStringLiteral("kalman"),
         QJsonObject{{QStringLiteral("L"), matrixToJson(d.L)}, {QStringLiteral("P"), matrixToJson(d.P)}}},
    };
}

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

void printText(const QString& preset, const core::RunToRunPlant& plant, const core::LqgWeights& w,
               const core::LqgDesign& d) {
    const core::SteadyStateVariances v = core::analyseSteadyState(plant, core::lqgControllerModel(plant, d));
    printLine(QStringLiteral("LQG run-to-run controller, preset %1: %2 control points, delay z = %3 parts, %4 states")
                  .arg(preset)
                  .arg(plant.pointCount())
                  .arg(plant.delay)
                  .arg(plant.stateCount()));
    printLine(
        QStringLiteral("Synthesis: %1 independent block(s), %2 Riccati doubling steps, worst relative residual %3")
            .arg(d.blocks.size())
            .arg(d.riccatiIterations)
            .arg(g(d.maxRelativeResidual, 2)));
    printLine(QString());
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7")
                  .arg(QStringLiteral("x, mm"), 8)
                  .arg(QStringLiteral("k_i"), 5)
                  .arg(QStringLiteral("R1"), 6)
                  .arg(QStringLiteral("R2"), 6)
                  .arg(QStringLiteral("open σ², mm²"), 13)
                  .arg(QStringLiteral("LQG σ², mm²"), 13)
                  .arg(QStringLiteral("k_eff"), 7));
    for (int i = 0; i < plant.pointCount(); ++i)
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7   %8")
                      .arg(plant.xMm[static_cast<std::size_t>(i)], 8, 'f', 1)
                      .arg(plant.gain(i), 5, 'g', 3)
                      .arg(w.R1(i, i), 6, 'g', 3)
                      .arg(w.R2(i, i), 6, 'g', 3)
                      .arg(v.available ? g(v.openMm2(i)) : QStringLiteral("unbounded"), 13)
                      .arg(v.available ? g(v.closedMm2(i)) : QStringLiteral("n/a"), 13)
                      .arg(v.available ? g(v.kEff(i), 3) : QStringLiteral("n/a"), 7)
                      .arg(QString::fromStdString(plant.disturbances[static_cast<std::size_t>(i)].describe())));
    printLine(QString());
    printLine(QStringLiteral("u(k) = -K x(k|k); x(k|k) = x(k|k-1) + L (y(k) - C x(k|k-1)). Matrices: --json."));
}

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("lqg"),
                         QStringLiteral("Designs the run-to-run LQG controller of a scenario preset (paper 000): plant "
                                        "state space, noise, weights, LQ gain K and Kalman gain L."));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("Scenario preset name or JSON file (default paper-2012)."), QStringLiteral("name"),
                     kDefaultPreset);
    parser.addOption(QStringLiteral("delay"),
                     QStringLiteral("Transport delay z in parts, 1..8 (default: the preset's)."), QStringLiteral("z"));
    parser.parse(arguments);
    std::optional<int> delay;
    if (parser.isSet(QStringLiteral("delay")))
        delay = static_cast<int>(parser.integer(QStringLiteral("delay"), 1, core::kMaxDelay));
    const QString preset = parser.value(QStringLiteral("preset"));
    const core::RunToRunSetup setup = config::loadRunToRunSetup(preset, delay);
    const core::RunToRunPlant plant = core::buildRunToRunPlant(setup.plant);
    const core::LqgDesign design = core::designLqg(plant, setup.weights);
    if (parser.json())
        printJson(toJson(plant, setup.weights, design));
    else
        printText(preset, plant, setup.weights, design);
    return kExitOk;
}

}  // namespace

Command makeLqgCommand() {
    return {QStringLiteral("lqg"), QStringLiteral("Design the run-to-run LQG controller: gains, Riccati solutions"),
            run};
}

}  // namespace tt::cli
