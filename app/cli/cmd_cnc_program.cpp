// trueturn cnc-program: the part program of a set-up for a CNC that takes TrueTurn's corrections between parts
// (docs/protocols/cnc.md): LinuxCNC, the cutter path drawn through numbered parameters (profile mode) or the
// nominal path with the tool's X wear applied by G43.2 (wear mode).
#include <QJsonArray>
#include <QJsonObject>
#include <cmath>
#include <numbers>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/loop_scenario.h"
#include "devices/linuxcnc/linuxcnc_program.h"

namespace tt::cli {

namespace {

void addOptions(CommandParser& p) {
    p.addOption(QStringLiteral("preset"), QStringLiteral("The set-up (preset name or JSON file)."),
                QStringLiteral("NAME"));
    p.addOption(QStringLiteral("dialect"), QStringLiteral("The CNC: linuxcnc."), QStringLiteral("linuxcnc"),
                QStringLiteral("linuxcnc"));
    p.addOption(QStringLiteral("parametric"),
                QStringLiteral("Profile mode: the corrections are parameters #FIRST.. (one per control point, then the "
                               "part number), set by TrueTurn between parts."),
                QStringLiteral("FIRST"));
    p.addOption(
        QStringLiteral("wear-tool"),
        QStringLiteral("Wear mode instead: the nominal path; the X wear of tool entry N is added by G43.2 H N."),
        QStringLiteral("N"));
    p.addOption(QStringLiteral("out"), QStringLiteral("The program file to write."), QStringLiteral("F.ngc"));
    p.addOption(QStringLiteral("x-mode"), QStringLiteral("X words: diameter (G7) or radius (G8)."),
                QStringLiteral("diameter|radius"), QStringLiteral("diameter"));
    p.addOption(QStringLiteral("units"), QStringLiteral("Program units: mm (G21) or inch (G20)."),
                QStringLiteral("mm|inch"), QStringLiteral("mm"));
    p.addOption(QStringLiteral("feed"), QStringLiteral("Finishing feed, mm/rev (G95; default: the set-up's)."),
                QStringLiteral("F"));
    p.addOption(QStringLiteral("feed-per-minute"), QStringLiteral("Feed in mm/min (G94) instead."),
                QStringLiteral("F"));
    p.addOption(QStringLiteral("rpm"),
                QStringLiteral("Spindle speed (G97 S M3; default: from the set-up's cutting "
                               "speed; 0: no spindle words)."),
                QStringLiteral("N"));
    p.addOption(QStringLiteral("tool"), QStringLiteral("Tool number (T M6 G43)."), QStringLiteral("N"),
                QStringLiteral("1"));
    p.addOption(QStringLiteral("z-origin"), QStringLiteral("Machine Z of the part's left end, mm."),
                QStringLiteral("Z"), QStringLiteral("0"));
    p.addOption(QStringLiteral("z-direction"), QStringLiteral("Machine Z = origin + direction x part z."),
                QStringLiteral("+1|-1"), QStringLiteral("-1"));
    p.addOption(QStringLiteral("largest-total"),
                QStringLiteral("The program refuses to cut with a correction beyond this, radial mm (default: the "
                               "set-up's correction limit)."),
                QStringLiteral("MM"));
    p.addOption(QStringLiteral("no-feed-forward"),
                QStringLiteral("Leave out the feed-forward of the systematic model (an open-loop path)."));
}

devices::linuxcnc::ProgramOptions programOptions(const CommandParser& p, const config::LoopScenario& scenario) {
    devices::linuxcnc::ProgramOptions o;
    const bool parametric = p.isSet(QStringLiteral("parametric"));
    if (parametric == p.isSet(QStringLiteral("wear-tool")))
        throw UsageError("give exactly one of --parametric FIRST (profile mode) and --wear-tool N (wear mode)");
    const long long points = static_cast<long long>(scenario.control.plant.points.size());
    if (parametric) {
        o.firstParameter = static_cast<int>(p.integer(QStringLiteral("parametric"), 31, 5000 - points));
    } else {
        o.firstParameter = 0;
        o.wearTool = static_cast<int>(p.integer(QStringLiteral("wear-tool"), 1, 99999));
    }
    o.conventions.diameterMode =
        p.choice(QStringLiteral("x-mode"), {QStringLiteral("diameter"), QStringLiteral("radius")}) ==
        QLatin1String("diameter");
    o.conventions.inch =
        p.choice(QStringLiteral("units"), {QStringLiteral("mm"), QStringLiteral("inch")}) == QLatin1String("inch");
    const double feed = scenario.lathe ? scenario.lathe->cutting.feedMmPerRev : 0.25;
    if (p.isSet(QStringLiteral("feed")) && p.isSet(QStringLiteral("feed-per-minute")))
        throw UsageError("give one of --feed (mm/rev) and --feed-per-minute (mm/min)");
    o.feedPerMinute = p.isSet(QStringLiteral("feed-per-minute"));
    o.feed = o.feedPerMinute ? p.number(QStringLiteral("feed-per-minute"), 0.001, 100000.0)
                             : (p.isSet(QStringLiteral("feed")) ? p.number(QStringLiteral("feed"), 0.001, 5.0) : feed);
    const double speed = scenario.lathe ? scenario.lathe->cutting.cuttingSpeedMPerMin : 46.3;
    o.spindleRpm =
        p.isSet(QStringLiteral("rpm"))
            ? static_cast<int>(p.integer(QStringLiteral("rpm"), 0, 10000))
            : static_cast<int>(std::lround(1000.0 * speed / (std::numbers::pi * scenario.nominalDiameterMm)));
    o.toolNumber = static_cast<int>(p.integer(QStringLiteral("tool"), 1, 99999));
    o.zOriginMm = p.number(QStringLiteral("z-origin"), -100000.0, 100000.0);
    o.zDirection =
        p.choice(QStringLiteral("z-direction"), {QStringLiteral("+1"), QStringLiteral("-1")}) == QLatin1String("+1")
            ? 1
            : -1;
    const double limit = scenario.control.limits.maxAbsMm;
    o.largestTotalMm = p.isSet(QStringLiteral("largest-total")) ? p.number(QStringLiteral("largest-total"), 0.001, 5.0)
                                                                : (std::isfinite(limit) && limit <= 5.0 ? limit : 0.5);
    o.notes = {"set-up " + p.value(QStringLiteral("preset")).toStdString()};
    return o;
}

QJsonObject toJson(const QString& out, const devices::linuxcnc::ProgramOptions& o,
                   const devices::ParametricProgramJob& job, const core::ShaftScenario& scenario) {
    QJsonArray points;
    for (const double z : job.pointZMm)
        points.append(z);
    QJsonObject json{
        {QStringLiteral("file"), out},
        {QStringLiteral("dialect"), QStringLiteral("linuxcnc")},
        {QStringLiteral("mode"), o.firstParameter ? QStringLiteral("profile") : QStringLiteral("wear")},
        {QStringLiteral("points_z_mm"), points},
        {QStringLiteral("path_samples"), static_cast<qint64>(job.pathZMm.size())},
        {QStringLiteral("feed_forward"), !job.feedForwardMm.empty()},
        {QStringLiteral("interpolation"),
         QString::fromStdString(core::interpolationMethodName(scenario.interpolation))},
        {QStringLiteral("x_mode"), o.conventions.diameterMode ? QStringLiteral("diameter") : QStringLiteral("radius")},
        {QStringLiteral("units"), o.conventions.inch ? QStringLiteral("inch") : QStringLiteral("mm")},
        {QStringLiteral("largest_total_mm"), o.largestTotalMm}};
    if (o.firstParameter)
        json.insert(
            QStringLiteral("parameters"),
            QJsonObject{{QStringLiteral("first"), o.firstParameter},
                        {QStringLiteral("count"), static_cast<qint64>(job.pointZMm.size())},
                        {QStringLiteral("part_number"), o.firstParameter + static_cast<qint64>(job.pointZMm.size())}});
    else
        json.insert(QStringLiteral("wear_tool"), o.wearTool);
    return json;
}

int runCncProgram(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("cnc-program"),
                         QStringLiteral("Writes the part program of a set-up for a CNC that takes TrueTurn's "
                                        "corrections between parts: LinuxCNC, the cutter path through numbered "
                                        "parameters (profile) or the nominal path with the tool's X wear (wear)."));
    addOptions(parser);
    parser.parse(arguments);
    parser.choice(QStringLiteral("dialect"), {QStringLiteral("linuxcnc")});
    const QString out = parser.required(QStringLiteral("out"));
    config::LoopScenario scenario;
    try {
        scenario = config::loadLoopScenario(parser.required(QStringLiteral("preset")));
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--preset: ") + e.what());
    }
    const devices::linuxcnc::ProgramOptions options = programOptions(parser, scenario);
    devices::ParametricProgramJob job;
    std::string program;
    try {
        job = devices::linuxcnc::programJob(
            scenario.loopConfig(!parser.isSet(QStringLiteral("no-feed-forward")), std::nullopt), options);
        program = devices::writeParametricProgram(job);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    writeOutputFile(out, QByteArray::fromStdString(program));
    if (parser.json())
        printJson(toJson(out, options, job, scenario));
    else
        printLine(QStringLiteral("LinuxCNC part program for %1 (%2 mode, %3 path samples) written to %4")
                      .arg(parser.value(QStringLiteral("preset")),
                           options.firstParameter ? QStringLiteral("profile") : QStringLiteral("wear"))
                      .arg(job.pathZMm.size())
                      .arg(out));
    return kExitOk;
}

}  // namespace

Command makeCncProgramCommand() {
    return {QStringLiteral("cnc-program"),
            QStringLiteral("the part program for a CNC that takes the corrections between parts (LinuxCNC: "
                           "parameters or tool wear)"),
            runCncProgram};
}

}  // namespace tt::cli
