#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <algorithm>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "app/cli/run_interrupt.h"
#include "config/corner_config.h"
#include "config/corrective_net_json.h"
#include "core/common/operation_cancelled.h"
#include "core/sim/feed_drives/corner_work_run.h"

namespace tt::cli {

namespace {

constexpr long long kMaxSeed = 9007199254740991LL;
constexpr int kAxisComparisonMoves = 40;

void addCommonOptions(CommandParser& parser) {
    parser.addOption(
        QStringLiteral("preset"),
        QStringLiteral("Corrective-pulse preset or JSON file. Default: %1.").arg(config::kDefaultCornerPreset),
        QStringLiteral("NAME|FILE.json"), config::kDefaultCornerPreset);
    parser.addOption(QStringLiteral("moves"), QStringLiteral("Number of moves, 1 .. 10000 (default: the preset's)."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("seed"),
                     QStringLiteral("Seed of the moves drawn from the preset's speed ranges (train: default the "
                                    "preset's training seed; run: that seed + 1, moves never trained on)."),
                     QStringLiteral("S"));
}

core::CornerScenario loadScenario(const CommandParser& parser) {
    try {
        return config::loadCornerScenario(parser.value(QStringLiteral("preset")));
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("--preset: %1").arg(QString::fromStdString(e.what())).toStdString());
    }
}

int movesOption(const CommandParser& parser, int fallback) {
    return parser.isSet(QStringLiteral("moves")) ? static_cast<int>(parser.integer(QStringLiteral("moves"), 1, 10000))
                                                 : fallback;
}

unsigned long long seedOption(const CommandParser& parser, unsigned long long fallback) {
    return parser.isSet(QStringLiteral("seed"))
               ? static_cast<unsigned long long>(parser.integer(QStringLiteral("seed"), 0, kMaxSeed))
               : fallback;
}

QJsonObject axisJson(const core::AxisPulseSummary& s) {
    return QJsonObject{{QStringLiteral("mean_abs_amplitude_v"), s.meanAbsAmplitudeV},
                       {QStringLiteral("mean_error_mm"), QJsonObject{{QStringLiteral("without"), s.meanWithoutMm},
                                                                     {QStringLiteral("with"), s.meanWithMm}}},
                       {QStringLiteral("reduction_pct"), s.reductionPct}};
}

/// Reports corner work through `progress`; cancels (false) once Ctrl-C or SIGTERM asked to stop.
core::CornerProgress cancellableProgress(ProgressPrinter& progress) {
    return [&progress](const std::string& stage, int done, int total) {
        progress.report(stage, done, total);
        return !InterruptGuard::stopRequested().load();
    };
}

// ---- corner train ----------------------------------------------------------------------------------

int runTrain(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("corner train"),
                         QStringLiteral("Trains the corrective-pulse network of the feed drives (paper 002): the best "
                                        "pulse amplitude of each training move is found on the simulator by a "
                                        "bracketed 1-D search of U = k1 e_max + k2 e_mean, then a 4-10-1 network "
                                        "learns it from the motor speeds before and after the corner."));
    addCommonOptions(parser);
    parser.addOption(QStringLiteral("out"), QStringLiteral("Where to save the network (JSON)."),
                     QStringLiteral("NET.json"));
    addProgressOption(parser);
    parser.parse(arguments);
    const QString out = parser.required(QStringLiteral("out"));
    core::CornerScenario scenario = loadScenario(parser);
    const int moves = movesOption(parser, scenario.training.moves);
    if (moves < 10) throw UsageError("--moves: training needs at least 10 moves");
    const unsigned long long seed = seedOption(parser, scenario.training.seed);
    const InterruptGuard interrupts;
    ProgressPrinter progress(parser.isSet(QStringLiteral("progress")), "");
    std::optional<core::CornerNetTraining> training;
    try {
        training.emplace(core::trainCornerNet(scenario, moves, seed, cancellableProgress(progress)));
    } catch (const core::OperationCancelled&) {
        return reportCancelled(progress, "corner train", "no network was written");
    }
    progress.finish();
    const core::CornerNetTraining& trained = *training;
    config::CornerNetFile file{trained.net, scenario.pulse, scenario.name, core::toNetSamples(trained.examples)};
    writeOutputFile(out, config::cornerNetToBytes(file));

    // Compare the axes on the first moves: the same search with the pulse on the other drive.
    const std::size_t compared = std::min<std::size_t>(trained.examples.size(), kAxisComparisonMoves);
    const std::vector<core::CornerExample> first(trained.examples.begin(),
                                                 trained.examples.begin() + static_cast<std::ptrdiff_t>(compared));
    core::PulseSettings other = scenario.pulse;
    other.axis = scenario.pulse.axis == core::FeedAxis::X ? core::FeedAxis::Z : core::FeedAxis::X;
    std::vector<core::CornerMove> firstMoves;
    for (const core::CornerExample& e : first)
        firstMoves.push_back(e.move);
    const core::AxisPulseSummary own = core::summarisePulses(scenario.pulse.axis, first);
    const core::AxisPulseSummary otherSummary = core::summarisePulses(
        other.axis,
        core::findPulseTargets(scenario.drives, scenario.cost, other, scenario.training.search, firstMoves));
    const core::AxisPulseSummary all = core::summarisePulses(scenario.pulse.axis, trained.examples);
    const core::NetTrainingRecord& r = trained.net.record();
    if (parser.json()) {
        QJsonObject comparison{{QStringLiteral("moves"), static_cast<int>(compared)}};
        comparison.insert(QString::fromLatin1(core::toString(own.axis)), axisJson(own));
        comparison.insert(QString::fromLatin1(core::toString(otherSummary.axis)), axisJson(otherSummary));
        printJson(QJsonObject{
            {QStringLiteral("preset"), QString::fromStdString(scenario.name)},
            {QStringLiteral("moves"), moves},
            {QStringLiteral("seed"), static_cast<qint64>(seed)},
            {QStringLiteral("out"), out},
            {QStringLiteral("axis"), QString::fromLatin1(core::toString(scenario.pulse.axis))},
            {QStringLiteral("best_pulses"), axisJson(all)},
            {QStringLiteral("network"),
             QJsonObject{{QStringLiteral("hidden"), trained.net.weights().hiddenCount()},
                         {QStringLiteral("epochs"), r.epochs},
                         {QStringLiteral("best_epoch"), r.bestEpoch},
                         {QStringLiteral("stop_reason"), QString::fromStdString(r.stopReason)},
                         {QStringLiteral("training_rms_v"), r.trainingRmsV},
                         {QStringLiteral("validation_rms_v"), r.validationRmsV}}},
            {QStringLiteral("axis_comparison"), comparison},
        });
        return kExitOk;
    }
    printLine(QStringLiteral("Corrective pulse on %1, preset %2: %3 training moves (seed %4)")
                  .arg(QString::fromLatin1(core::toString(scenario.pulse.axis)).toUpper(),
                       QString::fromStdString(scenario.name))
                  .arg(moves)
                  .arg(seed));
    printLine(QStringLiteral("Best pulses: mean trajectory error %1 -> %2 mm (-%3 %), mean |amplitude| %4 V")
                  .arg(all.meanWithoutMm, 0, 'f', 5)
                  .arg(all.meanWithMm, 0, 'f', 5)
                  .arg(all.reductionPct, 0, 'f', 1)
                  .arg(all.meanAbsAmplitudeV, 0, 'f', 3));
    printLine(
        QStringLiteral("Network 4-%1-1: %2 epochs (best %3, %4), RMS amplitude error %5 V training, %6 V validation")
            .arg(trained.net.weights().hiddenCount())
            .arg(r.epochs)
            .arg(r.bestEpoch)
            .arg(QString::fromStdString(r.stopReason))
            .arg(r.trainingRmsV, 0, 'f', 4)
            .arg(r.validationRmsV, 0, 'f', 4));
    for (const core::AxisPulseSummary& s : {own, otherSummary})
        printLine(QStringLiteral("Pulse on %1 (first %2 moves): -%3 %, mean |amplitude| %4 V")
                      .arg(QString::fromLatin1(core::toString(s.axis)).toUpper())
                      .arg(compared)
                      .arg(s.reductionPct, 0, 'f', 1)
                      .arg(s.meanAbsAmplitudeV, 0, 'f', 3));
    printLine(QStringLiteral("Saved %1").arg(out));
    return kExitOk;
}

// ---- corner (work run) ------------------------------------------------------------------------------

QJsonObject factorsJson(const core::DriveFactors& f, double rmsUm) {
    return QJsonObject{{QStringLiteral("friction"), f.friction},
                       {QStringLiteral("inertia"), f.inertia},
                       {QStringLiteral("gain"), f.velocityGain},
                       {QStringLiteral("encoder_rms_um"), rmsUm}};
}

QJsonObject eventJson(const core::CornerRetrainEvent& e) {
    const core::CandidateVerdict& v = e.verdict;
    const core::DriveEstimate& id = e.identified;
    return QJsonObject{
        {QStringLiteral("move"), e.move},
        {QStringLiteral("reason"), QString::fromStdString(e.reason)},
        {QStringLiteral("accepted"), v.accepted},
        {QStringLiteral("failure"),
         v.accepted ? QJsonValue(QJsonValue::Null) : QJsonValue(QString::fromStdString(v.failure))},
        {QStringLiteral("model_updated"), e.modelUpdated},
        {QStringLiteral("identified"), QJsonObject{{QStringLiteral("x"), factorsJson(id.factors.x, id.xRmsUm)},
                                                   {QStringLiteral("z"), factorsJson(id.factors.z, id.zRmsUm)}}},
        {QStringLiteral("validation_cost_mm"),
         QJsonObject{{QStringLiteral("kept"), v.keptCostMm}, {QStringLiteral("candidate"), v.candidateCostMm}}},
    };
}

/// The monitor's difference over its last full window since the last retraining, %, or null.
QJsonValue lastDifferencePct(const core::CornerWorkResult& r, int window) {
    const int since = r.retrains.empty() ? 0 : r.retrains.back().move + 1;
    for (int i = static_cast<int>(r.checks.size()) - 1; i >= since; --i)
        if (r.checks[static_cast<std::size_t>(i)].corners >= window)
            return 100.0 * r.checks[static_cast<std::size_t>(i)].differenceFraction;
    return QJsonValue(QJsonValue::Null);
}

QJsonObject workJson(const core::CornerWorkResult& r, const core::CornerDrift& drift,
                     const core::DriftMonitorSettings& monitor) {
    QJsonArray moves;
    for (const core::CornerWorkMove& m : r.moves)
        moves.append(QJsonObject{{QStringLiteral("vx1"), m.move.x1RadPerS},
                                 {QStringLiteral("vz1"), m.move.z1RadPerS},
                                 {QStringLiteral("vx2"), m.move.x2RadPerS},
                                 {QStringLiteral("vz2"), m.move.z2RadPerS},
                                 {QStringLiteral("error_without_mm"), m.without.meanErrorMm},
                                 {QStringLiteral("error_with_mm"), m.with.meanErrorMm},
                                 {QStringLiteral("amplitude_v"), m.amplitudeV}});
    QJsonArray events;
    for (const core::CornerRetrainEvent& e : r.retrains)
        events.append(eventJson(e));
    const QJsonValue driftJson =
        r.driftAtMove < 0
            ? QJsonValue(QJsonValue::Null)
            : QJsonValue(QJsonObject{{QStringLiteral("kind"), QString::fromLatin1(core::toString(drift.kind))},
                                     {QStringLiteral("axis"), QString::fromLatin1(core::toString(drift.axis))},
                                     {QStringLiteral("factor"), drift.factor},
                                     {QStringLiteral("at_move"), r.driftAtMove}});
    return QJsonObject{
        {QStringLiteral("moves"), moves},
        {QStringLiteral("mean_error_mm"),
         QJsonObject{{QStringLiteral("without"), r.meanWithoutMm}, {QStringLiteral("with"), r.meanWithMm}}},
        {QStringLiteral("reduction_pct"), r.reductionPct},
        {QStringLiteral("retrain_events"), events},
        {QStringLiteral("reduction_after_retrain_pct"),
         r.reductionAfterRetrainPct ? QJsonValue(*r.reductionAfterRetrainPct) : QJsonValue(QJsonValue::Null)},
        {QStringLiteral("drift"), driftJson},
        {QStringLiteral("monitor"),
         QJsonObject{{QStringLiteral("threshold_pct"), 100.0 * monitor.thresholdFraction},
                     {QStringLiteral("window_corners"), monitor.windowCorners},
                     {QStringLiteral("last_difference_pct"), lastDifferencePct(r, monitor.windowCorners)}}},
    };
}

void printWork(const QString& source, const core::CornerWorkResult& r, const core::CornerDrift& drift) {
    printLine(QStringLiteral("Corrective pulse, network %1: %2 moves").arg(source).arg(r.moves.size()));
    printLine(QStringLiteral("Mean trajectory error %1 mm without the pulse, %2 mm with it (-%3 %)")
                  .arg(r.meanWithoutMm, 0, 'f', 5)
                  .arg(r.meanWithMm, 0, 'f', 5)
                  .arg(r.reductionPct, 0, 'f', 1));
    if (r.driftAtMove >= 0)
        printLine(QStringLiteral("The machine drifted from move %1 on: %2 %3 x%4")
                      .arg(r.driftAtMove)
                      .arg(QString::fromLatin1(core::toString(drift.axis)).toUpper(),
                           QString::fromLatin1(core::toString(drift.kind)))
                      .arg(drift.factor, 0, 'f', 2));
    for (const core::CornerRetrainEvent& e : r.retrains)
        printLine((e.verdict.accepted ? QStringLiteral("Retrained after move %1: %2")
                                      : QStringLiteral("Retraining after move %1 refused: %2"))
                      .arg(e.move)
                      .arg(QString::fromStdString(e.reason)));
    if (r.reductionAfterRetrainPct)
        printLine(QStringLiteral("After the first retraining: -%1 %").arg(*r.reductionAfterRetrainPct, 0, 'f', 1));
}

/// The drift the options ask for; a drift that leaves a drive unable to move is refused.
core::CornerDrift driftOption(const CommandParser& parser, const core::CornerScenario& scenario) {
    core::CornerDrift drift;
    drift.kind = core::driveDriftKindFromString(
        parser
            .choice(QStringLiteral("drift-kind"),
                    {QStringLiteral("friction"), QStringLiteral("gain"), QStringLiteral("inertia")})
            .toStdString());
    drift.axis = core::feedAxisFromString(
        parser.choice(QStringLiteral("drift-axis"), {QStringLiteral("x"), QStringLiteral("z")}).toStdString().c_str());
    if (!parser.isSet(QStringLiteral("drift"))) return drift;
    drift.factor = parser.number(QStringLiteral("drift"), core::kMinDriveDriftFactor, core::kMaxDriveDriftFactor);
    try {
        (void)core::scaledDrives(scenario.drives, core::driftFactors(drift.kind, drift.axis, drift.factor));
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("--drift: %1").arg(QString::fromStdString(e.what())).toStdString());
    }
    return drift;
}

int runWork(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("corner"),
                         QStringLiteral("Runs moves with the corrective pulse of the feed drives (paper 002) on the "
                                        "simulated machine and reports the trajectory error with and without it. The "
                                        "drift monitor retrains the network when the measured error leaves the "
                                        "predicted one. `trueturn corner train --help` trains a network."));
    addCommonOptions(parser);
    parser.addOption(QStringLiteral("net"),
                     QStringLiteral("Network saved by `corner train` (default: train one on the preset's moves)."),
                     QStringLiteral("NET.json"));
    parser.addOption(QStringLiteral("drift"),
                     QStringLiteral("From the middle move on, multiply what --drift-kind names on the drive of "
                                    "--drift-axis by F, 0.5 .. 3."),
                     QStringLiteral("F"));
    parser.addOption(QStringLiteral("drift-kind"),
                     QStringLiteral("What drifts: friction (ways and screw), gain (the drive's motor speed per volt "
                                    "of velocity command) or inertia (the load at the motor). Default: friction."),
                     QStringLiteral("friction|gain|inertia"), QStringLiteral("friction"));
    parser.addOption(QStringLiteral("drift-axis"), QStringLiteral("The drive that drifts. Default: z."),
                     QStringLiteral("x|z"), QStringLiteral("z"));
    addProgressOption(parser);
    parser.addOption(QStringLiteral("no-retrain"),
                     QStringLiteral("The drift monitor only watches: no retraining (for comparison)."));
    parser.parse(arguments);
    core::CornerScenario scenario = loadScenario(parser);
    const int moves = movesOption(parser, scenario.evaluationMoves);
    const unsigned long long seed = seedOption(parser, scenario.training.seed + 1);
    const core::CornerDrift drift = driftOption(parser, scenario);
    const InterruptGuard interrupts;
    ProgressPrinter progress(parser.isSet(QStringLiteral("progress")), "");
    QString source;
    std::optional<config::CornerNetFile> file;
    if (parser.isSet(QStringLiteral("net"))) {
        const QString path = parser.required(QStringLiteral("net"));
        try {
            file = config::cornerNetFromBytes(readInputFile(path, core::kDocumentLimits));
        } catch (const std::invalid_argument& e) {
            throw inputError(path, e.what());
        }
        scenario.pulse = file->pulse;  // the network's amplitudes belong to the pulse it was trained for
        source = path;
    } else {
        std::optional<core::CornerNetTraining> training;
        try {
            training.emplace(core::trainCornerNet(scenario, scenario.training.moves, scenario.training.seed,
                                                  cancellableProgress(progress)));
        } catch (const core::OperationCancelled&) {
            return reportCancelled(progress, "corner", "nothing was written");
        }
        const core::CornerNetTraining& trained = *training;
        file = config::CornerNetFile{trained.net, scenario.pulse, scenario.name, core::toNetSamples(trained.examples)};
        source =
            QStringLiteral("trained on %1 moves of seed %2").arg(scenario.training.moves).arg(scenario.training.seed);
    }
    const std::vector<core::CornerMove> work = core::drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, moves, seed);
    core::CorrectiveNet net = file->net;
    const bool retrain = !parser.isSet(QStringLiteral("no-retrain"));
    core::CornerWorkResult result;
    try {
        result = core::runCornerWork(scenario, net, file->samples, work, drift, retrain, cancellableProgress(progress));
    } catch (const core::OperationCancelled&) {
        return reportCancelled(progress, "corner", "nothing was written");
    }
    progress.finish();
    if (parser.json())
        printJson(workJson(result, drift, scenario.retraining.monitor));
    else
        printWork(source, result, drift);
    return kExitOk;
}

int runCorner(const QStringList& arguments) {
    if (!arguments.isEmpty() && arguments.first() == QStringLiteral("train")) return runTrain(arguments.mid(1));
    return runWork(arguments);
}

}  // namespace

Command makeCornerCommand() {
    return {QStringLiteral("corner"),
            QStringLiteral("neural corrective pulse of the feed drives at corners: train, run, retrain on drift"),
            runCorner};
}

}  // namespace tt::cli
