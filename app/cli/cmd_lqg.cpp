#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "config/plant_config.h"
#include "core/control/lqg_design.h"
#include "core/control/margins.h"
#include "core/control/run_to_run_plant.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::cli {

namespace {

const QString kDefaultPreset = QStringLiteral("paper-2012");

QJsonValue optionalJson(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
}

/// Per-channel robustness figures (null: no such crossing, the loop tolerates any change of that kind).
QJsonObject marginsJson(const core::LoopMargins& m) {
    QJsonArray gain, gainLower, phase, delay, extra, disk, diskGain, diskPhase, peak;
    for (const core::ChannelMargins& c : m.channels) {
        gain.append(optionalJson(c.gain));
        gainLower.append(optionalJson(c.gainLower));
        phase.append(optionalJson(c.phaseDeg));
        delay.append(optionalJson(c.delayParts));
        extra.append(c.extraPartsTolerated);
        disk.append(c.disk);
        diskGain.append(c.diskGainUpper > 0.0 ? QJsonValue(c.diskGainUpper) : QJsonValue(QJsonValue::Null));
        diskPhase.append(c.diskPhaseDeg);
        peak.append(c.sensitivityPeak);
    }
    return QJsonObject{{QStringLiteral("gain"), gain},
                       {QStringLiteral("gain_lower"), gainLower},
                       {QStringLiteral("phase_deg"), phase},
                       {QStringLiteral("delay_parts"), delay},
                       {QStringLiteral("extra_parts_tolerated"), extra},
                       {QStringLiteral("disk"), disk},
                       {QStringLiteral("disk_gain"), diskGain},
                       {QStringLiteral("disk_phase_deg"), diskPhase},
                       {QStringLiteral("sensitivity_peak"), peak},
                       {QStringLiteral("closed_loop_stable"), m.closedLoopStable}};
}

/// Stable English warnings: `delay_margin_below_one_part` per point, `closed_loop_unstable`.
QJsonArray warningsJson(const core::LoopMargins& m) {
    QJsonArray out;
    if (!m.closedLoopStable)
        out.append(QJsonObject{{QStringLiteral("kind"), QStringLiteral("closed_loop_unstable")},
                               {QStringLiteral("message"), QStringLiteral("the designed loop is unstable")}});
    for (std::size_t i = 0; i < m.channels.size(); ++i) {
        const core::ChannelMargins& c = m.channels[i];
        const bool continuousShort = c.delayParts && *c.delayParts < 1.0;
        if (!m.closedLoopStable || (!continuousShort && c.extraPartsTolerated >= 1)) continue;
        out.append(QJsonObject{
            {QStringLiteral("kind"), QStringLiteral("delay_margin_below_one_part")},
            {QStringLiteral("point"), static_cast<int>(i)},
            {QStringLiteral("delay_parts"), optionalJson(c.delayParts)},
            {QStringLiteral("extra_parts_tolerated"), c.extraPartsTolerated},
            {QStringLiteral("message"),
             QStringLiteral("point %1: a plant one part slower than the model destabilises the loop (delay margin "
                            "%2 parts, %3 whole extra parts tolerated)")
                 .arg(i + 1)
                 .arg(c.delayParts ? QString::number(*c.delayParts, 'f', 2) : QStringLiteral("unbounded"))
                 .arg(c.extraPartsTolerated)}});
    }
    return out;
}

QJsonObject toJson(const core::RunToRunPlant& plant, const core::LqgWeights& w, const core::LqgDesign& d) {
    QJsonArray points;
    for (double x : plant.xMm)
        points.append(QJsonObject{{QStringLiteral("x_mm"), x}});
    using config::matrixToJson;
    const core::LoopMargins margins = core::lqgMargins(plant, d);
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
        {QStringLiteral("margins"), marginsJson(margins)},
        {QStringLiteral("warnings"), warningsJson(margins)},
    };
}

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

QString optionalText(const std::optional<double>& v, int precision = 3) {
    return v ? g(*v, precision) : QStringLiteral("none");
}

void printMargins(const core::LoopMargins& m, const core::RunToRunPlant& plant) {
    printLine(QStringLiteral("Robustness, loop broken at one point (the others closed):%1")
                  .arg(m.closedLoopStable ? QString() : QStringLiteral(" THE NOMINAL LOOP IS UNSTABLE")));
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7")
                  .arg(QStringLiteral("x, mm"), 8)
                  .arg(QStringLiteral("gain"), 7)
                  .arg(QStringLiteral("phase, °"), 9)
                  .arg(QStringLiteral("delay, parts"), 13)
                  .arg(QStringLiteral("+parts ok"), 10)
                  .arg(QStringLiteral("disk α"), 7)
                  .arg(QStringLiteral("max|S|"), 7));
    for (std::size_t i = 0; i < m.channels.size(); ++i) {
        const core::ChannelMargins& c = m.channels[i];
        const bool flagged = (c.delayParts && *c.delayParts < 1.0) || c.extraPartsTolerated < 1;
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6 %7%8")
                      .arg(plant.xMm[i], 8, 'f', 1)
                      .arg(optionalText(c.gain), 7)
                      .arg(optionalText(c.phaseDeg), 9)
                      .arg(optionalText(c.delayParts), 13)
                      .arg(c.extraPartsTolerated, 10)
                      .arg(g(c.disk, 3), 7)
                      .arg(g(c.sensitivityPeak, 3), 7)
                      .arg(flagged ? QStringLiteral("  WARNING: one extra part of delay destabilises") : QString()));
    }
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
    printMargins(core::lqgMargins(plant, d), plant);
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
