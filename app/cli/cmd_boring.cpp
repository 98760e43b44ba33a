#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QTextStream>
#include <cmath>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/boring_config.h"
#include "core/run/boring_simulation.h"

namespace tt::cli {

namespace {

QJsonValue optional(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
}

QJsonObject toJson(const QString& preset, const core::BoringScenario& s, const core::BoringResult& r) {
    QJsonObject out;
    out.insert(QStringLiteral("method"), QString::fromLatin1(core::toString(r.method)));
    out.insert(QStringLiteral("preset"), preset);
    out.insert(QStringLiteral("bore_error_mm"),
               QJsonObject{{QStringLiteral("max"), r.boreErrorMaxMm},
                           {QStringLiteral("rms"), r.boreErrorRmsMm},
                           {QStringLiteral("on"), QStringLiteral("diameter")},
                           {QStringLiteral("gauged_from_mm"), r.gaugedFromMm},
                           {QStringLiteral("gauged_to_mm"), r.gaugedToMm},
                           {QStringLiteral("max_full_length"), r.boreErrorMaxFullLengthMm}});
    out.insert(QStringLiteral("deflection_mm"), QJsonObject{{QStringLiteral("max"), r.deflectionMaxMm}});
    out.insert(QStringLiteral("force_estimate_error_pct"), optional(r.forceEstimateErrorPct));
    out.insert(QStringLiteral("force_estimate_error_max_pct"), optional(r.forceEstimateErrorMaxPct));
    out.insert(QStringLiteral("force_n"),
               QJsonObject{{QStringLiteral("mean"), r.forceMeanN}, {QStringLiteral("max"), r.forceMaxN}});
    out.insert(QStringLiteral("coulomb_friction_to_mean_force"),
               r.forceMeanN > 0.0 ? QJsonValue(s.drive.coulombFrictionN / r.forceMeanN) : QJsonValue(QJsonValue::Null));
    out.insert(QStringLiteral("stiffness_n_per_mm"), QJsonObject{{QStringLiteral("tool_table"), r.stiffnessUsedNPerMm},
                                                                 {QStringLiteral("true"), r.trueStiffnessNPerMm}});
    out.insert(QStringLiteral("slenderness_l_over_d"), core::slendernessRatio(s.tool));
    out.insert(QStringLiteral("estimates"), r.estimates);
    out.insert(QStringLiteral("holding_cycles"), r.holdingCycles);
    if (r.lastHoldProblem != core::ReadingProblem::None)
        out.insert(QStringLiteral("last_hold_reason"), QString::fromLatin1(core::toString(r.lastHoldProblem)));
    if (r.calibration)
        out.insert(QStringLiteral("probe_calibration"),
                   QJsonObject{{QStringLiteral("points"), r.calibration->points},
                               {QStringLiteral("degree"), r.calibration->degree},
                               {QStringLiteral("rms_residual_um"), r.calibration->rmsResidualUm},
                               {QStringLiteral("max_table_error_um"), r.calibration->maxTableErrorUm},
                               {QStringLiteral("image_crc"), static_cast<qint64>(r.calibration->imageCrc)}});
    return out;
}

void printText(const QString& preset, const core::BoringScenario& s, const core::BoringResult& r) {
    printLine(QStringLiteral("Boring pass, preset %1, compensation: %2").arg(preset, core::toString(r.method)));
    printLine(QStringLiteral("Tool %1: L/d = %2, stiffness %3 N/mm in the tool table (real bar %4 N/mm)")
                  .arg(QString::fromStdString(s.tool.name))
                  .arg(core::slendernessRatio(s.tool), 0, 'f', 1)
                  .arg(r.stiffnessUsedNPerMm, 0, 'f', 0)
                  .arg(r.trueStiffnessNPerMm, 0, 'f', 0));
    printLine(
        QStringLiteral("Radial cutting force: mean %1 N, max %2 N; guideway Coulomb friction %3 N (%4 x the mean)")
            .arg(r.forceMeanN, 0, 'f', 0)
            .arg(r.forceMaxN, 0, 'f', 0)
            .arg(s.drive.coulombFrictionN, 0, 'f', 0)
            .arg(s.drive.coulombFrictionN / std::max(r.forceMeanN, 1e-9), 0, 'f', 1));
    printLine(
        QStringLiteral("Bore diameter error from %1 to %2 mm: max %3 mm, RMS %4 mm (max over the whole bore %5 mm)")
            .arg(r.gaugedFromMm, 0, 'f', 0)
            .arg(r.gaugedToMm, 0, 'f', 0)
            .arg(r.boreErrorMaxMm, 0, 'f', 4)
            .arg(r.boreErrorRmsMm, 0, 'f', 4)
            .arg(r.boreErrorMaxFullLengthMm, 0, 'f', 4));
    printLine(QStringLiteral("Largest bar deflection %1 mm").arg(r.deflectionMaxMm, 0, 'f', 4));
    if (r.forceEstimateErrorPct)
        printLine(QStringLiteral("Force estimate error: RMS %1 %, max %2 %")
                      .arg(*r.forceEstimateErrorPct, 0, 'f', 1)
                      .arg(*r.forceEstimateErrorMaxPct, 0, 'f', 1));
    if (r.calibration)
        printLine(QStringLiteral("Probe calibrated on the rig: %1 points, degree %2, table error at the points %3 µm")
                      .arg(r.calibration->points)
                      .arg(r.calibration->degree)
                      .arg(r.calibration->maxTableErrorUm, 0, 'f', 2));
}

void writeTrace(const QString& path, const core::BoringResult& r) {
    QByteArray csv;
    QTextStream out(&csv);
    out << "time_s,z_mm,diameter_error_mm,deflection_mm,offset_mm,force_n,estimated_force_n\n";
    for (const core::BoringTracePoint& p : r.trace)
        out << p.timeS << ',' << p.zMm << ',' << p.diameterErrorMm << ',' << p.deflectionMm << ',' << p.offsetMm << ','
            << p.forceN << ',' << (std::isfinite(p.estimatedForceN) ? QString::number(p.estimatedForceN) : QString())
            << '\n';
    out.flush();
    writeOutputFile(path, csv);
}

int runBoring(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("boring"),
                         QStringLiteral("Simulates a finishing bore with a slender boring bar (paper 001) and its "
                                        "in-process deflection compensation: from the cross-feed current with "
                                        "dither, from the probe mandrel, or none. Bore errors are on the diameter."));
    parser.addOption(QStringLiteral("preset"), QStringLiteral("Scenario preset or JSON file. Default: heavy-boring."),
                     QStringLiteral("NAME|FILE.json"), QStringLiteral("heavy-boring"));
    parser.addOption(QStringLiteral("method"),
                     QStringLiteral("Compensation: current, probe or none. Default: current."),
                     QStringLiteral("current|probe|none"), QStringLiteral("current"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Random seed (overrides the preset's)."),
                     QStringLiteral("S"));
    parser.addOption(QStringLiteral("dither-mm"),
                     QStringLiteral("Dither amplitude A, mm, 0.005 .. 0.05 (overrides the preset's)."),
                     QStringLiteral("A"));
    parser.addOption(QStringLiteral("dither-period-s"),
                     QStringLiteral("Dither period T (one forward and one reverse stroke), s, 0.2 .. 2 (overrides the "
                                    "preset's)."),
                     QStringLiteral("T"));
    parser.addOption(QStringLiteral("trace"), QStringLiteral("Write one CSV row per PLC cycle in the bore."),
                     QStringLiteral("FILE.csv"));
    parser.parse(arguments);
    const QString preset = parser.value(QStringLiteral("preset"));
    const core::BoringMethod method = core::boringMethodFromString(
        parser
            .choice(QStringLiteral("method"),
                    {QStringLiteral("current"), QStringLiteral("probe"), QStringLiteral("none")})
            .toStdString());
    core::BoringScenario scenario = [&] {
        try {
            return config::loadBoringScenario(preset);
        } catch (const std::invalid_argument& e) {
            throw UsageError(QStringLiteral("--preset: %1").arg(QString::fromStdString(e.what())).toStdString());
        }
    }();
    if (parser.isSet(QStringLiteral("seed")))
        scenario.seed = static_cast<unsigned long long>(parser.integer(QStringLiteral("seed"), 0, 9007199254740991LL));
    if (parser.isSet(QStringLiteral("dither-mm")))
        scenario.dither.amplitudeMm = parser.number(QStringLiteral("dither-mm"), 0.005, 0.05);
    if (parser.isSet(QStringLiteral("dither-period-s")))
        scenario.dither.periodS = parser.number(QStringLiteral("dither-period-s"), 0.2, 2.0);
    const core::BoringResult result = core::runBoring(scenario, method);
    if (parser.isSet(QStringLiteral("trace"))) writeTrace(parser.required(QStringLiteral("trace")), result);
    if (parser.json())
        printJson(toJson(preset, scenario, result));
    else
        printText(preset, scenario, result);
    return kExitOk;
}

}  // namespace

Command makeBoringCommand() {
    return {QStringLiteral("boring"),
            QStringLiteral("boring-bar deflection compensation on the simulator (current with dither, probe, none)"),
            runBoring};
}

}  // namespace tt::cli
