#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "config/preset_library.h"
#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/feed_schedule_check.h"
#include "devices/parsers/gcode_writer.h"

namespace tt::cli {

namespace {

config::DeformationModelFile loadModel(const QString& path) {
    try {
        const QJsonDocument doc = QJsonDocument::fromJson(readInputFile(path, core::kDocumentLimits));
        if (!doc.isObject()) throw std::invalid_argument("not a JSON object (write it with fit-deformation --json)");
        return config::deformationModelFromJson(doc.object());
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
}

core::FeedScheduleRequest readRequest(const CommandParser& p) {
    core::FeedScheduleRequest r;
    // Wide ranges here: the scheduler names the limit that matters (the model's range, f_mm > 0, ...).
    r.depthMm = p.number(QStringLiteral("depth"), -100.0, 100.0);
    r.feedMinMmPerRev = p.number(QStringLiteral("feed-min"), -100.0, 100.0);
    r.feedMaxMmPerRev = p.number(QStringLiteral("feed-max"), -100.0, 100.0);
    r.feedStepMmPerRev = p.number(QStringLiteral("feed-step"), -100.0, 100.0);
    r.zStartMm = p.number(QStringLiteral("z-start"), -100000.0, 100000.0);
    r.zEndMm = p.number(QStringLiteral("z-end"), -100000.0, 100000.0);
    const bool level = p.isSet(QStringLiteral("level"));
    const bool fraction = p.isSet(QStringLiteral("level-fraction"));
    if (level == fraction) throw UsageError("give exactly one of --level Y (um) and --level-fraction Q (0 .. 1)");
    if (level) r.levelUm = p.number(QStringLiteral("level"), -1e6, 1e6);
    if (fraction) r.levelFraction = p.number(QStringLiteral("level-fraction"), 0.0, 1.0);
    if (p.isSet(QStringLiteral("min-length")))
        r.minLengthMm = p.number(QStringLiteral("min-length"), -100000.0, 100000.0);
    return r;
}

/// The simulator set-up the model's experiments were cut on (for --verify).
config::FeedSchedulingSetup verificationSetup(const config::DeformationModelFile& model, const QString& path) {
    if (model.preset.isEmpty())
        throw UsageError(QStringLiteral("--verify: %1 does not name the simulator set-up its experiments were cut on "
                                        "(source.preset); fit it from a deformation-experiment CSV or with "
                                        "fit-deformation --preset")
                             .arg(path)
                             .toStdString());
    try {
        return config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(model.preset));
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("--verify: the set-up %1 of %2: %3")
                             .arg(model.preset, path, QString::fromStdString(e.what()))
                             .toStdString());
    }
}

QJsonObject toJson(const core::FeedSchedule& s, const core::MachiningTimes& t,
                   const std::optional<core::FeedScheduleCheck>& check, const QString& gcode,
                   devices::GCodeDialect dialect) {
    QJsonArray segments;
    for (const core::FeedSegment& g : s.segments)
        segments.append(QJsonObject{{QStringLiteral("z_from"), g.zFromMm},
                                    {QStringLiteral("z_to"), g.zToMm},
                                    {QStringLiteral("f"), g.feedMmPerRev},
                                    {QStringLiteral("y_from_um"), g.yFromUm},
                                    {QStringLiteral("y_to_um"), g.yToUm}});
    QJsonObject out{
        {QStringLiteral("yc_um"), s.levelUm},
        {QStringLiteral("y1_um"), s.y1Um},
        {QStringLiteral("y2_um"), s.y2Um},
        {QStringLiteral("f_start"), s.feedStartMmPerRev},
        {QStringLiteral("f_end"), s.feedEndMmPerRev},
        {QStringLiteral("skipped_short"), s.skippedShort},
        {QStringLiteral("segments"), segments},
        {QStringLiteral("time_s"), QJsonObject{{QStringLiteral("schedule"), t.scheduleS},
                                               {QStringLiteral("fmin"), t.feedMinS},
                                               {QStringLiteral("fmax"), t.feedMaxS},
                                               {QStringLiteral("saved_vs_fmin_pct"), t.savedVsFeedMinPct()}}}};
    if (check)
        out.insert(QStringLiteral("verify"),
                   QJsonObject{{QStringLiteral("max_deviation_pct"), check->maxDeviationPct},
                               {QStringLiteral("worst_z"), check->worstZMm},
                               {QStringLiteral("worst_y_um"), check->worstYUm},
                               {QStringLiteral("within_10_pct"), check->maxDeviationPct <= 10.0},
                               {QStringLiteral("fmax_excess_pct"), check->feedMaxExcessPct},
                               {QStringLiteral("fmax_worst_z"), check->feedMaxWorstZMm},
                               {QStringLiteral("fmin_shortfall_pct"), check->feedMinShortfallPct}});
    if (!gcode.isEmpty())
        out.insert(QStringLiteral("gcode"), QJsonObject{{QStringLiteral("file"), gcode},
                                                        {QStringLiteral("dialect"),
                                                         QString::fromStdString(devices::gcodeDialectName(dialect))}});
    return out;
}

void printText(const core::FeedSchedule& s, const core::MachiningTimes& t,
               const std::optional<core::FeedScheduleCheck>& check, const QString& gcode) {
    printLine(QStringLiteral("Feed schedule (paper 004): Yc %1 um in [Y1 %2, Y2 %3] um; start feed %4, end feed %5 "
                             "mm/rev; %6 segments (%7 feed steps skipped as shorter than L_min)")
                  .arg(s.levelUm, 0, 'f', 2)
                  .arg(s.y1Um, 0, 'f', 2)
                  .arg(s.y2Um, 0, 'f', 2)
                  .arg(s.feedStartMmPerRev, 0, 'f', 4)
                  .arg(s.feedEndMmPerRev, 0, 'f', 4)
                  .arg(s.segments.size())
                  .arg(s.skippedShort));
    printLine(QStringLiteral("  z from mm   z to mm   feed mm/rev   Y from um   Y to um"));
    for (const core::FeedSegment& g : s.segments)
        printLine(QStringLiteral("  %1 %2 %3 %4 %5")
                      .arg(g.zFromMm, 9, 'f', 2)
                      .arg(g.zToMm, 9, 'f', 2)
                      .arg(g.feedMmPerRev, 13, 'f', 4)
                      .arg(g.yFromUm, 11, 'f', 2)
                      .arg(g.yToUm, 9, 'f', 2));
    printLine(QStringLiteral("Machining time %1 s; constant fmin %2 s (%3 % saved), constant fmax %4 s")
                  .arg(t.scheduleS, 0, 'f', 1)
                  .arg(t.feedMinS, 0, 'f', 1)
                  .arg(t.savedVsFeedMinPct(), 0, 'f', 1)
                  .arg(t.feedMaxS, 0, 'f', 1));
    if (check)
        printLine(QStringLiteral("On the simulator: the deformation stays within %1 % of Yc (worst at z = %2 mm, Y %3 "
                                 "um); constant fmax exceeds Yc by up to %4 % (at z = %5 mm)")
                      .arg(check->maxDeviationPct, 0, 'f', 2)
                      .arg(check->worstZMm, 0, 'f', 1)
                      .arg(check->worstYUm, 0, 'f', 2)
                      .arg(check->feedMaxExcessPct, 0, 'f', 1)
                      .arg(check->feedMaxWorstZMm, 0, 'f', 1));
    if (!gcode.isEmpty()) printLine(QStringLiteral("CNC program written to %1").arg(gcode));
}

int runScheduleFeed(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("schedule-feed"),
                         QStringLiteral("Schedules the feed along a pass so that the force deformation stays at the "
                                        "level Yc (paper 004), from the model Y(a, f, z) of fit-deformation, and "
                                        "writes the CNC program."));
    parser.addOption(QStringLiteral("model"), QStringLiteral("The model file of fit-deformation --json."),
                     QStringLiteral("FILE.json"));
    parser.addOption(QStringLiteral("depth"), QStringLiteral("Depth of cut a, mm."), QStringLiteral("A"));
    parser.addOption(QStringLiteral("feed-min"), QStringLiteral("Smallest feed fmin, mm/rev."), QStringLiteral("F"));
    parser.addOption(QStringLiteral("feed-max"), QStringLiteral("Largest feed fmax, mm/rev."), QStringLiteral("F"));
    parser.addOption(QStringLiteral("feed-step"), QStringLiteral("The machine's feed increment f_mm, mm/rev (> 0)."),
                     QStringLiteral("F"));
    parser.addOption(QStringLiteral("z-start"), QStringLiteral("Where the pass starts, mm (the model's z)."),
                     QStringLiteral("Z"));
    parser.addOption(QStringLiteral("z-end"), QStringLiteral("Where the pass ends, mm."), QStringLiteral("Z"));
    parser.addOption(QStringLiteral("level"), QStringLiteral("The deformation to hold, Yc, um (in [Y1, Y2])."),
                     QStringLiteral("Y"));
    parser.addOption(QStringLiteral("level-fraction"),
                     QStringLiteral("Yc as a fraction of [Y1, Y2]: 0 = Y1 (quality), 1 = Y2 (productivity)."),
                     QStringLiteral("Q"));
    parser.addOption(QStringLiteral("min-length"), QStringLiteral("Shortest segment L_min, mm (default 0)."),
                     QStringLiteral("L"));
    parser.addOption(QStringLiteral("dialect"), QStringLiteral("G-code dialect: fanuc or linuxcnc (default fanuc)."),
                     QStringLiteral("fanuc|linuxcnc"), QStringLiteral("fanuc"));
    parser.addOption(QStringLiteral("gcode"), QStringLiteral("Write the CNC program of the pass."),
                     QStringLiteral("FILE.nc"));
    parser.addOption(QStringLiteral("verify"),
                     QStringLiteral("Machine the scheduled pass on the simulator the model's experiments came from."));
    parser.parse(arguments);
    const QString modelPath = parser.required(QStringLiteral("model"));
    const core::FeedScheduleRequest request = readRequest(parser);
    const devices::GCodeDialect dialect = devices::gcodeDialectFromName(
        parser.choice(QStringLiteral("dialect"), {QStringLiteral("fanuc"), QStringLiteral("linuxcnc")}).toStdString());
    const config::DeformationModelFile model = loadModel(modelPath);
    if (!model.job)
        throw UsageError(QStringLiteral("%1 has no machine job (spindle speed, coolant, Z origin): fit it with "
                                        "fit-deformation --preset NAME|FILE.json naming the set-up")
                             .arg(modelPath)
                             .toStdString());
    const core::FeedSchedule schedule = core::scheduleFeed(model.model, request);
    const core::MachiningTimes times = core::machiningTimes(schedule, request, model.job->spindleRpm);

    std::optional<core::FeedScheduleCheck> check;
    if (parser.isSet(QStringLiteral("verify"))) {
        const config::FeedSchedulingSetup setup = verificationSetup(model, modelPath);
        check = core::checkFeedSchedule(core::LathePass(setup.lathe, request.depthMm), schedule, request);
    }
    QString gcode;
    if (parser.isSet(QStringLiteral("gcode"))) {
        gcode = parser.required(QStringLiteral("gcode"));
        devices::FeedPassJob job = *model.job;
        job.depthMm = request.depthMm;
        job.dialect = dialect;
        const std::string program =
            devices::writeFeedScheduleGCode(config::feedPassProgram(schedule, request, model), job);
        writeOutputFile(gcode, QByteArray::fromStdString(program));
    }
    if (parser.json())
        printJson(toJson(schedule, times, check, gcode, dialect));
    else
        printText(schedule, times, check, gcode);
    return kExitOk;
}

}  // namespace

Command makeScheduleFeedCommand() {
    return {QStringLiteral("schedule-feed"),
            QStringLiteral("feed schedule against force deformation and its CNC program (paper 004)"), runScheduleFeed};
}

}  // namespace tt::cli
