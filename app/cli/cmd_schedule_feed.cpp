#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/deformation_csv.h"
#include "config/deformation_model_config.h"
#include "config/feed_refinement_json.h"
#include "config/feed_schedule_config.h"
#include "config/preset_library.h"
#include "core/control/feed_refinement_design.h"
#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/feed_refinement.h"
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
    r.switchRule = core::feedSwitchRuleFromName(
        p.choice(QStringLiteral("switch"), {QStringLiteral("level"), QStringLiteral("centred")}).toStdString());
    return r;
}

core::FeedRefinementOptions readRefineOptions(const CommandParser& p) {
    core::FeedRefinementOptions o;
    if (p.isSet(QStringLiteral("refine-rounds")))
        o.maxRounds = static_cast<int>(p.integer(QStringLiteral("refine-rounds"), 1, 10));
    if (p.isSet(QStringLiteral("refine-bars")))
        o.maxBarsPerRound = static_cast<int>(p.integer(QStringLiteral("refine-bars"), 1, 20));
    if (p.isSet(QStringLiteral("refine-gauges")))
        o.gaugesPerBar = static_cast<int>(p.integer(QStringLiteral("refine-gauges"), 4, 200));
    return o;
}

/// The measurements the model was fitted on (--experiment), or none.
core::DeformationSamples loadExperiment(const CommandParser& p) {
    if (!p.isSet(QStringLiteral("experiment"))) return {};
    const QString path = p.required(QStringLiteral("experiment"));
    try {
        return config::parseDeformationCsv(readInputFile(path)).samples;
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
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

/// What the command worked out: the schedule (the refined one after --refine), its check on the
/// simulator, the refinement or the proposal of one.
struct Outcome {
    core::FeedSchedule schedule;
    config::DeformationModelFile model;  ///< the model the schedule rests on
    std::optional<core::FeedScheduleCheck> check;
    std::optional<core::FeedRefinement> refinement;
    std::optional<core::RefinementProposal> proposal;
    int maxRounds = 0;

    bool misses() const { return check && check->maxDeviationPct > core::kFeedScheduleTolerancePct; }
};

QJsonObject toJson(const Outcome& o, const core::FeedScheduleRequest& request, const core::MachiningTimes& t,
                   const QString& gcode, devices::GCodeDialect dialect) {
    const core::FeedSchedule& s = o.schedule;
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
        {QStringLiteral("depth_mm"), request.depthMm},
        {QStringLiteral("switch"), QLatin1String(core::feedSwitchRuleName(request.switchRule))},
        {QStringLiteral("f_start"), s.feedStartMmPerRev},
        {QStringLiteral("f_end"), s.feedEndMmPerRev},
        {QStringLiteral("skipped_short"), s.skippedShort},
        {QStringLiteral("model_deviation_pct"), s.modelDeviationPct()},
        {QStringLiteral("segments"), segments},
        {QStringLiteral("time_s"), QJsonObject{{QStringLiteral("schedule"), t.scheduleS},
                                               {QStringLiteral("fmin"), t.feedMinS},
                                               {QStringLiteral("fmax"), t.feedMaxS},
                                               {QStringLiteral("saved_vs_fmin_pct"), t.savedVsFeedMinPct()}}}};
    if (o.check) out.insert(QStringLiteral("verify"), config::feedScheduleCheckToJson(*o.check));
    if (o.refinement) out.insert(QStringLiteral("refine"), config::feedRefinementToJson(*o.refinement, o.maxRounds));
    if (o.proposal) {
        QJsonObject proposal = config::refinementProposalToJson(*o.proposal);
        const std::string advice = core::feedStepAdvice(s, request);
        if (!advice.empty()) proposal.insert(QStringLiteral("advice"), QString::fromStdString(advice));
        out.insert(QStringLiteral("proposal"), proposal);
    }
    if (!gcode.isEmpty())
        out.insert(QStringLiteral("gcode"), QJsonObject{{QStringLiteral("file"), gcode},
                                                        {QStringLiteral("dialect"),
                                                         QString::fromStdString(devices::gcodeDialectName(dialect))}});
    return out;
}

void printSchedule(const core::FeedSchedule& s, const core::MachiningTimes& t) {
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
}

QString barsText(const std::vector<core::RefinementBar>& bars) {
    QStringList feeds;
    for (const core::RefinementBar& b : bars)
        feeds << QStringLiteral("%1 (%2 points)").arg(b.feedMmPerRev, 0, 'f', 4).arg(b.zMm.size());
    return feeds.join(QStringLiteral(", "));
}

void printRefinement(const core::FeedRefinement& r) {
    printLine(QStringLiteral("Before the refinement: %1 % off Yc at z = %2 mm")
                  .arg(r.initialCheck.maxDeviationPct, 0, 'f', 2)
                  .arg(r.initialCheck.worstZMm, 0, 'f', 1));
    for (const core::FeedRefinementRound& round : r.rounds) {
        QString result = round.check ? QStringLiteral("%1 % off Yc at z = %2 mm")
                                           .arg(round.check->maxDeviationPct, 0, 'f', 2)
                                           .arg(round.check->worstZMm, 0, 'f', 1)
                                     : QString::fromStdString(round.problem);
        printLine(QStringLiteral("Round %1: %2 bars at mm/rev %3; local model on %4 measurements: %5")
                      .arg(round.round)
                      .arg(round.plan.bars.size())
                      .arg(barsText(round.plan.bars))
                      .arg(round.measurements)
                      .arg(result));
    }
}

void printText(const Outcome& o, const core::MachiningTimes& t, const QString& gcode) {
    if (o.refinement) printRefinement(*o.refinement);
    printSchedule(o.schedule, t);
    if (o.check)
        printLine(QStringLiteral("On the simulator: the deformation stays within %1 % of Yc (worst at z = %2 mm, Y %3 "
                                 "um); constant fmax exceeds Yc by up to %4 % (at z = %5 mm)")
                      .arg(o.check->maxDeviationPct, 0, 'f', 2)
                      .arg(o.check->worstZMm, 0, 'f', 1)
                      .arg(o.check->worstYUm, 0, 'f', 2)
                      .arg(o.check->feedMaxExcessPct, 0, 'f', 1)
                      .arg(o.check->feedMaxWorstZMm, 0, 'f', 1));
    if (o.proposal)
        printLine(QStringLiteral("Proposed targeted experiment at a = %1 mm: %2 bars, feeds mm/rev %3")
                      .arg(o.proposal->depthMm)
                      .arg(o.proposal->bars.size())
                      .arg(barsText(o.proposal->bars)));
    if (!gcode.isEmpty()) printLine(QStringLiteral("CNC program written to %1").arg(gcode));
}

/// The one line on stderr when the pass leaves the band: the worst z, its deviation and what next.
QString missReason(const Outcome& o, const core::FeedScheduleRequest& request) {
    const core::FeedScheduleCheck& c = *o.check;
    QString line = QStringLiteral(
                       "--verify: the pass leaves the +-%1 % band: %2 % off Yc = %3 um at z = %4 mm "
                       "(Y %5 um)")
                       .arg(core::kFeedScheduleTolerancePct, 0, 'f', 0)
                       .arg(c.maxDeviationPct, 0, 'f', 2)
                       .arg(o.schedule.levelUm, 0, 'f', 2)
                       .arg(c.worstZMm, 0, 'f', 1)
                       .arg(c.worstYUm, 0, 'f', 2);
    if (o.refinement)
        line += QStringLiteral(" after %1 refinement rounds (%2 bars)")
                    .arg(o.refinement->rounds.size())
                    .arg(o.refinement->barCount());
    else if (o.proposal)
        line += QStringLiteral("; --refine runs the proposed experiment (%1 bars at a = %2 mm)")
                    .arg(o.proposal->bars.size())
                    .arg(request.depthMm);
    const std::string advice = core::feedStepAdvice(o.schedule, request);
    if (!advice.empty()) line += QStringLiteral("; ") + QString::fromStdString(advice);
    return line;
}

/// --verify and --refine: machines the pass, refines the model when asked, proposes when not.
void verifyAndRefine(const CommandParser& p, Outcome& o, const core::FeedScheduleRequest& request,
                     const QString& modelPath) {
    const config::FeedSchedulingSetup setup = verificationSetup(o.model, modelPath);
    const core::FeedRefinementOptions options = readRefineOptions(p);
    const core::DeformationSamples measured = loadExperiment(p);
    const double sigma = o.model.statistics.residualSigmaUm;
    if (p.isSet(QStringLiteral("refine"))) {
        std::uint64_t seed = o.model.seed.value_or(1);
        if (p.isSet(QStringLiteral("seed")))
            seed = static_cast<std::uint64_t>(p.integer(QStringLiteral("seed"), 0, 4294967295LL));
        o.maxRounds = options.maxRounds;
        o.refinement = core::refineFeedSchedule(setup.lathe, o.model.model, sigma, measured, request, options, seed);
        o.check = o.refinement->initialCheck;
        if (const core::FeedRefinementRound* last = o.refinement->lastScheduled()) {
            o.schedule = *last->schedule;
            o.check = *last->check;
            o.model = config::refinedModelFile(*last->fit, o.model, o.refinement->barCount());
        }
        return;
    }
    o.check = core::checkFeedSchedule(core::LathePass(setup.lathe, request.depthMm), o.schedule, request);
    if (o.misses()) o.proposal = core::proposeRefinement(o.schedule, request, measured, sigma, options);
}

void addOptions(CommandParser& parser) {
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
    parser.addOption(QStringLiteral("switch"),
                     QStringLiteral("Where a feed step switches: level (the paper: where the next feed reaches Yc, Y "
                                    "stays below it) or centred (where the two feeds' mean is Yc: half the "
                                    "deviation). Default level."),
                     QStringLiteral("level|centred"), QStringLiteral("level"));
    parser.addOption(QStringLiteral("dialect"), QStringLiteral("G-code dialect: fanuc or linuxcnc (default fanuc)."),
                     QStringLiteral("fanuc|linuxcnc"), QStringLiteral("fanuc"));
    parser.addOption(QStringLiteral("gcode"), QStringLiteral("Write the CNC program of the pass."),
                     QStringLiteral("FILE.nc"));
    parser.addOption(QStringLiteral("verify"),
                     QStringLiteral("Machine the scheduled pass on the simulator the model's experiments came from. "
                                    "Outside +-10 % of Yc the command exits 3 naming the worst z (the JSON is still "
                                    "written) and proposes a targeted experiment."));
    parser.addOption(QStringLiteral("refine"),
                     QStringLiteral("With --verify: while the pass misses, machine the proposed bars on the "
                                    "simulator, refit the model at this depth, reschedule and verify again."));
    parser.addOption(QStringLiteral("refine-rounds"), QStringLiteral("Refinement rounds at most, 1 .. 10 (default 3)."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("refine-bars"), QStringLiteral("Bars per round at most, 1 .. 20 (default 6)."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("refine-gauges"),
                     QStringLiteral("Gauge points per bar, 4 .. 200 (default 33), chosen every 5 mm along the pass."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("experiment"),
                     QStringLiteral("The experiment CSV the model was fitted on: its bars at this depth join the "
                                    "refined model (default: the refinement starts from its own bars)."),
                     QStringLiteral("FILE.csv"));
    parser.addOption(QStringLiteral("seed"),
                     QStringLiteral("Seed of the micrometer's noise on the refinement's bars (default: the model's)."),
                     QStringLiteral("S"));
    parser.addOption(QStringLiteral("refined-model"), QStringLiteral("Write the refined model file here."),
                     QStringLiteral("FILE.json"));
}

int runScheduleFeed(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("schedule-feed"),
                         QStringLiteral("Schedules the feed along a pass so that the force deformation stays at the "
                                        "level Yc (paper 004), from the model Y(a, f, z) of fit-deformation, and "
                                        "writes the CNC program. Exit 3: --verify found the pass outside +-10 % of "
                                        "Yc."));
    addOptions(parser);
    parser.parse(arguments);
    const QString modelPath = parser.required(QStringLiteral("model"));
    const core::FeedScheduleRequest request = readRequest(parser);
    const devices::GCodeDialect dialect = devices::gcodeDialectFromName(
        parser.choice(QStringLiteral("dialect"), {QStringLiteral("fanuc"), QStringLiteral("linuxcnc")}).toStdString());
    Outcome o{{}, loadModel(modelPath), {}, {}, {}, 0};
    if (!o.model.job)
        throw UsageError(QStringLiteral("%1 has no machine job (spindle speed, coolant, Z origin): fit it with "
                                        "fit-deformation --preset NAME|FILE.json naming the set-up")
                             .arg(modelPath)
                             .toStdString());
    const bool refine = parser.isSet(QStringLiteral("refine"));
    if (refine && !parser.isSet(QStringLiteral("verify")))
        throw UsageError("--refine needs --verify (it refines while the verified pass misses)");
    o.schedule = core::scheduleFeed(o.model.model, request);
    if (parser.isSet(QStringLiteral("verify"))) verifyAndRefine(parser, o, request, modelPath);
    const core::MachiningTimes times = core::machiningTimes(o.schedule, request, o.model.job->spindleRpm);

    QString gcode;
    if (parser.isSet(QStringLiteral("gcode"))) {
        gcode = parser.required(QStringLiteral("gcode"));
        devices::FeedPassJob job = *o.model.job;
        job.depthMm = request.depthMm;
        job.dialect = dialect;
        const std::string program =
            devices::writeFeedScheduleGCode(config::feedPassProgram(o.schedule, request, o.model), job);
        writeOutputFile(gcode, QByteArray::fromStdString(program));
    }
    if (parser.isSet(QStringLiteral("refined-model")) && o.refinement && o.refinement->lastScheduled())
        writeOutputFile(parser.required(QStringLiteral("refined-model")),
                        QJsonDocument(config::deformationModelToJson(o.model)).toJson(QJsonDocument::Indented));
    if (parser.json())
        printJson(toJson(o, request, times, gcode, dialect));
    else
        printText(o, times, gcode);
    if (!o.misses()) return kExitOk;
    std::fprintf(stderr, "trueturn schedule-feed: %s\n", qPrintable(missReason(o, request)));
    return kExitOutOfTolerance;
}

}  // namespace

Command makeScheduleFeedCommand() {
    return {QStringLiteral("schedule-feed"),
            QStringLiteral("feed schedule against force deformation and its CNC program (paper 004)"), runScheduleFeed};
}

}  // namespace tt::cli
