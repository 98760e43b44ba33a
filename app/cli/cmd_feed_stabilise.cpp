#include <QRegularExpression>
#include <QString>
#include <optional>
#include <stdexcept>

#include "app/cli/cmd_feed_stabilise_output.h"
#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "config/hydraulic_feed_config.h"
#include "core/sim/hydraulic/feed_study.h"

namespace tt::cli {

namespace {

const QString kDefaultPreset = QStringLiteral("hydraulic-feed");

/// Runs `f`, turning the engine's std::invalid_argument into a UsageError that names the option.
template <typename F>
auto asUsage(const QString& option, F&& f) {
    try {
        return f();
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("%1: %2").arg(option, QString::fromStdString(e.what())).toStdString());
    }
}

double parseNumber(const QString& option, const QString& text, const QString& what) {
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok) throw UsageError(QStringLiteral("%1: '%2' is not a number (%3)").arg(option, text, what).toStdString());
    return v;
}

/// --load-step N@T and --load-ramp N@T+D.
void addLoadEvents(const CommandParser& parser, core::FeedLoadProfile& load) {
    static const QRegularExpression step(QStringLiteral("^([^@]+)@([^+]+)$"));
    static const QRegularExpression ramp(QStringLiteral("^([^@]+)@([^+]+)\\+(.+)$"));
    for (const QString& text : parser.values(QStringLiteral("load-step"))) {
        const QRegularExpressionMatch m = step.match(text);
        if (!m.hasMatch())
            throw UsageError(
                QStringLiteral("--load-step: '%1' is not FORCE_N@TIME_S (e.g. 3.23@0.02)").arg(text).toStdString());
        const double force = parseNumber(QStringLiteral("--load-step"), m.captured(1), QStringLiteral("force, N"));
        const double time = parseNumber(QStringLiteral("--load-step"), m.captured(2), QStringLiteral("time, s"));
        asUsage(QStringLiteral("--load-step"), [&] {
            load.addStep(time, force);
            return 0;
        });
    }
    for (const QString& text : parser.values(QStringLiteral("load-ramp"))) {
        const QRegularExpressionMatch m = ramp.match(text);
        if (!m.hasMatch())
            throw UsageError(QStringLiteral("--load-ramp: '%1' is not FORCE_N@START_S+DURATION_S (e.g. 3.23@0.02+0.1)")
                                 .arg(text)
                                 .toStdString());
        const double force = parseNumber(QStringLiteral("--load-ramp"), m.captured(1), QStringLiteral("force, N"));
        const double time = parseNumber(QStringLiteral("--load-ramp"), m.captured(2), QStringLiteral("start, s"));
        const double duration =
            parseNumber(QStringLiteral("--load-ramp"), m.captured(3), QStringLiteral("duration, s"));
        asUsage(QStringLiteral("--load-ramp"), [&] {
            load.addRamp(time, duration, force);
            return 0;
        });
    }
}

/// --set KEY=VALUE: any parameter by its preset key.
void applySettings(const CommandParser& parser, core::HydraulicFeedParams& params) {
    for (const QString& text : parser.values(QStringLiteral("set"))) {
        const qsizetype eq = text.indexOf(QLatin1Char('='));
        if (eq <= 0)
            throw UsageError(
                QStringLiteral("--set: '%1' is not KEY=VALUE (e.g. spool.damping_ratio=0.8)").arg(text).toStdString());
        const core::FeedParameterInfo& info = asUsage(QStringLiteral("--set"), [&]() -> const core::FeedParameterInfo& {
            return core::feedParameter(text.left(eq).trimmed().toStdString());
        });
        params.*(info.member) = parseNumber(QStringLiteral("--set"), text.mid(eq + 1), QString::fromLatin1(info.name));
    }
}

core::FeedScenario scenarioFrom(const CommandParser& parser, const QString& preset) {
    core::FeedScenario s =
        asUsage(QStringLiteral("--preset"), [&] { return config::loadHydraulicFeedScenario(preset); });
    if (parser.isSet(QStringLiteral("load-step")) || parser.isSet(QStringLiteral("load-ramp"))) {
        s.load = core::FeedLoadProfile{};
        addLoadEvents(parser, s.load);
    }
    applySettings(parser, s.params);
    if (parser.isSet(QStringLiteral("xi")))
        s.params.spoolDampingRatio = parser.number(QStringLiteral("xi"), 0.05, 10.0);
    if (parser.isSet(QStringLiteral("match"))) {
        s.params.spoolLapM = core::matchedSpoolLap(s.params);
        const double load = s.finalLoadN() > 0.0 ? s.finalLoadN() : s.load.maxForceN();
        if (load <= 0.0) throw UsageError("--match: the scenario has no load to design the gain for");
        s.params.amplifierGain =
            asUsage(QStringLiteral("--match"), [&] { return core::designAmplifierGain(s.params, load); });
    }
    if (parser.isSet(QStringLiteral("gain"))) s.params.amplifierGain = parser.number(QStringLiteral("gain"), 0.0, 1e5);
    if (parser.isSet(QStringLiteral("start")))
        s.run.fromRest = parser.choice(QStringLiteral("start"), {QStringLiteral("running"), QStringLiteral("rest")}) ==
                         QStringLiteral("rest");
    if (parser.isSet(QStringLiteral("duration")))
        s.run.durationS = parser.number(QStringLiteral("duration"), 1e-3, core::FeedLoadProfile::kMaxTimeS);
    s.run.sampleS = std::max(s.run.sampleS, s.run.durationS / 20000.0);
    asUsage(QStringLiteral("parameters"), [&] {
        core::validate(s.params);
        return 0;
    });
    return s;
}

std::vector<double> sweepValues(const CommandParser& parser, const FeedReport& r) {
    if (!parser.isSet(QStringLiteral("sweep-values"))) {
        if (r.loadSweep) return core::defaultLoadSweepValues();
        return asUsage(QStringLiteral("--sweep"),
                       [&] { return core::defaultSweepValues(*r.sweepKind, r.scenario, r.compared()); });
    }
    std::vector<double> values;
    for (const QString& v : parser.value(QStringLiteral("sweep-values")).split(QLatin1Char(',')))
        values.push_back(parseNumber(QStringLiteral("--sweep-values"), v, QStringLiteral("a sweep value")));
    return values;
}

void addOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("preset"), QStringLiteral("Scenario preset or JSON file. Default: hydraulic-feed."),
                     QStringLiteral("NAME|FILE.json"), kDefaultPreset);
    parser.addOption(QStringLiteral("regulator"),
                     QStringLiteral("Which run the top-level figures describe (all three are simulated): the feedback "
                                    "of the measured feed, the paper's feed-forward of the measured force, or none. "
                                    "Default: feedback."),
                     QStringLiteral("feedforward|feedback|off"), QStringLiteral("feedback"));
    parser.addOption(QStringLiteral("load-step"),
                     QStringLiteral("The load becomes FORCE newtons at TIME seconds; repeat for more steps. Replaces "
                                    "the preset's load (with --load-ramp)."),
                     QStringLiteral("N@T"));
    parser.addOption(QStringLiteral("load-ramp"),
                     QStringLiteral("The load moves linearly to FORCE newtons from START over DURATION seconds."),
                     QStringLiteral("N@T+D"));
    parser.addOption(QStringLiteral("start"),
                     QStringLiteral("Carriage running at the set feed, or at rest (the paper's eq. 22)."),
                     QStringLiteral("running|rest"));
    parser.addOption(QStringLiteral("xi"), QStringLiteral("Spool damping ratio (0.05 .. 10)."), QStringLiteral("X"));
    parser.addOption(QStringLiteral("gain"), QStringLiteral("Amplifier gain K_a, V/V (0 .. 1e5)."),
                     QStringLiteral("K"));
    parser.addOption(QStringLiteral("set"),
                     QStringLiteral("Any parameter by its preset key, e.g. spool.time_constant_s=0.005; repeatable."),
                     QStringLiteral("KEY=VALUE"));
    parser.addOption(QStringLiteral("match"),
                     QStringLiteral("Redesign after --set: the spool lap matching the bias, the gain making up the "
                                    "final load's leakage (--gain still wins)."));
    parser.addOption(QStringLiteral("sweep"),
                     QStringLiteral("Step responses for a sweep of xi or of the gain (with the regulator), or of the "
                                    "load (a step to each load with every regulator)."),
                     QStringLiteral("xi|gain|load"));
    parser.addOption(
        QStringLiteral("sweep-values"),
        QStringLiteral("The sweep's values, comma separated (default: xi 0.2 .. 2; gain 0 .. 2 x design "
                       "for the feed-forward, factors 0.25 .. 6 on K_p for the feedback; load 0.5 .. 6 N)."),
        QStringLiteral("A,B,..."));
    parser.addOption(QStringLiteral("duration"), QStringLiteral("Simulated time, s (default: the preset's)."),
                     QStringLiteral("S"));
    parser.addOption(QStringLiteral("csv"),
                     QStringLiteral("Write the time series (both runs, or every sweep member) as CSV."),
                     QStringLiteral("FILE.csv"));
}

/// The feed-forward's gain analysis (only for --regulator feedforward: the paper's regulator), the sensitivity.
void analyse(FeedReport& r) {
    const double load = r.scenario.finalLoadN();
    if (!(load > 0.0)) {
        r.stabilityNote = QStringLiteral("the scenario ends without load: nothing to regulate");
        return;
    }
    r.sensitivity = core::feedSensitivity(r.scenario.params, load, 0.1, r.compared());
    if (r.regulator != core::FeedRegulator::FeedForward) {
        r.stabilityNote = QStringLiteral("only with --regulator feedforward (it analyses the paper's regulator)");
        return;
    }
    try {
        r.stability = core::analyseStability(r.scenario.params, load);
    } catch (const std::invalid_argument& e) {
        r.stabilityNote = QString::fromStdString(e.what());  // no design point: the slot cannot make it up
    }
    if (r.stability && r.stability->gainLimit) r.check = core::crossCheckGainLimit(r.scenario, *r.stability->gainLimit);
}

void runSweep(const CommandParser& parser, FeedReport& r) {
    const std::vector<double> values = sweepValues(parser, r);
    if (r.loadSweep)
        r.loads = asUsage(QStringLiteral("--sweep-values"), [&] { return core::sweepLoad(r.scenario, values); });
    else
        r.sweep = asUsage(QStringLiteral("--sweep"),
                          [&] { return core::sweepFeed(r.scenario, *r.sweepKind, values, r.compared()); });
}

int runFeedStabilise(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("feed-stabilise"),
        QStringLiteral("Simulates the hydraulic feed drive of a finishing lathe with its feed stabiliser (paper 003): "
                       "sensor -> amplifier -> electromagnet -> spool flow regulator -> cylinder, integrated with an "
                       "adaptive Dormand-Prince stepper, without a regulator, with the paper's feed-forward and with "
                       "the feedback of the measured feed. Reports the steady feed, settling, how well the set feed "
                       "was held and the warnings, the feedback's margins, the feed-forward's stability boundary, the "
                       "parameters' sensitivity, and sweeps of xi, the gain or the load."));
    addOptions(parser);
    parser.parse(arguments);
    FeedReport r;
    r.preset = parser.value(QStringLiteral("preset"));
    r.regulator = core::feedRegulatorFromString(
        parser
            .choice(QStringLiteral("regulator"),
                    {QStringLiteral("feedforward"), QStringLiteral("feedback"), QStringLiteral("off")})
            .toStdString());
    if (parser.isSet(QStringLiteral("sweep"))) {
        const QString sweep = parser.choice(QStringLiteral("sweep"),
                                            {QStringLiteral("xi"), QStringLiteral("gain"), QStringLiteral("load")});
        r.loadSweep = sweep == QStringLiteral("load");
        if (!r.loadSweep) r.sweepKind = core::feedSweepKindFromString(sweep.toStdString());
    }
    r.scenario = scenarioFrom(parser, r.preset);
    r.feedbackDesign =
        asUsage(QStringLiteral("parameters"), [&] { return core::designFeedFeedback(r.scenario.params); });
    r.off = core::runFeedScenario(r.scenario, core::FeedRegulator::Off);
    r.feedForward = core::runFeedScenario(r.scenario, core::FeedRegulator::FeedForward);
    r.feedback = core::runFeedScenario(r.scenario, core::FeedRegulator::Feedback);
    analyse(r);
    if (r.sweepKind || r.loadSweep) runSweep(parser, r);
    if (parser.isSet(QStringLiteral("csv"))) writeFeedCsv(parser.required(QStringLiteral("csv")), r);
    if (parser.json())
        printJson(feedReportJson(r));
    else
        printFeedReport(r);
    return kExitOk;
}

}  // namespace

Command makeFeedStabiliseCommand() {
    return {QStringLiteral("feed-stabilise"),
            QStringLiteral("hydraulic feed stabilisation under a changing cutting force (paper 003): feedback, the "
                           "paper's feed-forward "
                           "or none; sweeps of xi, gain and load"),
            runFeedStabilise};
}

}  // namespace tt::cli
