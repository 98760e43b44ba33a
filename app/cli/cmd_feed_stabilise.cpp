#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>
#include <QString>
#include <optional>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/hydraulic_feed_config.h"
#include "config/hydraulic_feed_csv.h"
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

std::vector<double> sweepValues(const CommandParser& parser, core::FeedSweepKind kind, const core::FeedScenario& s) {
    if (!parser.isSet(QStringLiteral("sweep-values")))
        return asUsage(QStringLiteral("--sweep"), [&] { return core::defaultSweepValues(kind, s); });
    std::vector<double> values;
    for (const QString& v : parser.value(QStringLiteral("sweep-values")).split(QLatin1Char(',')))
        values.push_back(parseNumber(QStringLiteral("--sweep-values"), v, QStringLiteral("a sweep value")));
    return values;
}

QJsonObject metricsJson(const core::FeedRun& run) {
    return {{QStringLiteral("steady_feed_m_s"), run.feed.finalValue},
            {QStringLiteral("settling_s"), run.feed.settlingS},
            {QStringLiteral("overshoot_pct"), run.feed.overshootPct},
            {QStringLiteral("peak_deviation_m_s"), run.feed.peakDeviation},
            {QStringLiteral("spool_overshoot_pct"), run.opening.overshootPct},
            {QStringLiteral("settled"), run.feed.settled},
            {QStringLiteral("slot_fully_open"), run.slotFullyOpen}};
}

QJsonObject derivedJson(const core::FeedScenario& s) {
    const core::HydraulicFeedDerived d = core::deriveFeedQuantities(s.params);
    const double load = s.finalLoadN();
    return {{QStringLiteral("piston_area_m2"), d.pistonAreaM2},
            {QStringLiteral("cylinder_gain_per_m2"), d.cylinderGainPerM2},
            {QStringLiteral("cylinder_time_constant_s"), d.cylinderTimeConstantS},
            {QStringLiteral("pump_flow_m3_s"), d.pumpFlowM3PerS},
            {QStringLiteral("leakage_m3_s"), d.leakagePerNewtonM3PerS * load},
            {QStringLiteral("slot_gain_m2_s"), d.slotGainM2PerS},
            {QStringLiteral("coil_inductance_h"), d.coilInductanceH},
            {QStringLiteral("magnet_time_constant_s"), d.magnetTimeConstantS},
            {QStringLiteral("armature_gain_n_per_a2"), d.armatureGainNPerA2},
            {QStringLiteral("matched_lap_m"), d.biasSpoolM}};
}

QJsonValue optional(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
}

QJsonObject stabilityJson(const core::FeedStability& st, const std::optional<core::FeedBoundaryCheck>& check) {
    QJsonArray eigenvalues;
    for (Eigen::Index k = 0; k < st.atGain.eigenvalues.size(); ++k)
        eigenvalues.append(QJsonObject{{QStringLiteral("re"), st.atGain.eigenvalues(k).real()},
                                       {QStringLiteral("im"), st.atGain.eigenvalues(k).imag()}});
    QJsonObject out{{QStringLiteral("eigenvalues_per_s"), eigenvalues},
                    {QStringLiteral("stable"), st.atGain.stable()},
                    {QStringLiteral("loop_gain"), st.atGain.loopGain},
                    {QStringLiteral("design_gain"), st.designGain},
                    {QStringLiteral("gain_limit"), optional(st.gainLimit)},
                    {QStringLiteral("full_opening_gain"), optional(st.fullOpeningGain)}};
    if (check)
        out.insert(QStringLiteral("simulation_check"),
                   QJsonObject{{QStringLiteral("below_gain"), check->belowGain},
                               {QStringLiteral("predicted_feed_m_s"), check->predictedFeedMPerS},
                               {QStringLiteral("below_feed_m_s"), check->below.feed.finalValue},
                               {QStringLiteral("below_settles"), check->belowSettles},
                               {QStringLiteral("above_gain"), check->aboveGain},
                               {QStringLiteral("above_feed_m_s"), check->above.feed.finalValue},
                               {QStringLiteral("above_runs_away"), check->aboveRunsAway}});
    return out;
}

QJsonArray sensitivityJson(const std::vector<core::FeedSensitivity>& rows) {
    QJsonArray out;
    for (const core::FeedSensitivity& r : rows)
        out.append(QJsonObject{{QStringLiteral("parameter"), QString::fromStdString(r.key)},
                               {QStringLiteral("name"), QString::fromStdString(r.name)},
                               {QStringLiteral("nominal"), r.nominal},
                               {QStringLiteral("regulated_minus_pct"), r.onMinusPct},
                               {QStringLiteral("regulated_plus_pct"), r.onPlusPct},
                               {QStringLiteral("unregulated_minus_pct"), r.offMinusPct},
                               {QStringLiteral("unregulated_plus_pct"), r.offPlusPct},
                               {QStringLiteral("slot_fully_open"), r.fullyOpen}});
    return out;
}

QJsonArray sweepJson(core::FeedSweepKind kind, const std::vector<core::FeedSweepPoint>& points) {
    QJsonArray out;
    for (const core::FeedSweepPoint& p : points) {
        QJsonObject row = metricsJson(p.run);
        row.insert(QString::fromLatin1(core::toString(kind)), p.value);
        row.insert(QStringLiteral("oscillates"), p.oscillates);
        row.insert(QStringLiteral("stable"), p.stable);
        out.append(row);
    }
    return out;
}

/// Everything the command computes.
struct FeedReport {
    QString preset;
    core::FeedScenario scenario;
    bool regulatorOn = true;
    core::FeedRun with;
    core::FeedRun without;
    std::optional<core::FeedStability> stability;
    QString stabilityNote;  ///< why there is no stability analysis (no load, or more leakage than the slot passes)
    std::optional<core::FeedBoundaryCheck> check;
    std::vector<core::FeedSensitivity> sensitivity;
    std::optional<core::FeedSweepKind> sweepKind;
    std::vector<core::FeedSweepPoint> sweep;

    const core::FeedRun& chosen() const { return regulatorOn ? with : without; }
};

QJsonObject toJson(const FeedReport& r) {
    QJsonObject out = metricsJson(r.chosen());
    out.insert(QStringLiteral("preset"), r.preset);
    out.insert(QStringLiteral("regulator"), r.regulatorOn ? QStringLiteral("on") : QStringLiteral("off"));
    out.insert(QStringLiteral("start"), r.scenario.run.fromRest ? QStringLiteral("rest") : QStringLiteral("running"));
    out.insert(QStringLiteral("load_n"), r.scenario.finalLoadN());
    out.insert(QStringLiteral("with_regulator"), metricsJson(r.with));
    out.insert(QStringLiteral("without_regulator"), metricsJson(r.without));
    out.insert(QStringLiteral("parameters"), config::hydraulicFeedParamsToJson(r.scenario.params));
    out.insert(QStringLiteral("derived"), derivedJson(r.scenario));
    out.insert(QStringLiteral("stability"),
               r.stability ? QJsonValue(stabilityJson(*r.stability, r.check)) : QJsonValue(QJsonValue::Null));
    if (!r.stabilityNote.isEmpty()) out.insert(QStringLiteral("stability_note"), r.stabilityNote);
    out.insert(QStringLiteral("sensitivity"), sensitivityJson(r.sensitivity));
    if (r.sweepKind) {
        out.insert(QStringLiteral("sweep_of"), QString::fromLatin1(core::toString(*r.sweepKind)));
        out.insert(QStringLiteral("sweep"), sweepJson(*r.sweepKind, r.sweep));
    }
    return out;
}

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

QString metricsLine(const QString& what, const core::FeedRun& run) {
    return QStringLiteral("%1 %2 %3 %4 %5")
        .arg(what, -24)
        .arg(g(run.feed.finalValue), 12)
        .arg(QString::number(run.feed.settlingS, 'f', 4) + (run.feed.settled ? QString() : QStringLiteral("+")), 11)
        .arg(QString::number(run.feed.overshootPct, 'f', 2), 12)
        .arg(g(run.feed.peakDeviation, 3), 14);
}

void printStability(const FeedReport& r) {
    if (!r.stability) {
        printLine(QStringLiteral("Stability: not analysed, %1.").arg(r.stabilityNote));
        return;
    }
    const core::FeedStability& st = *r.stability;
    QStringList poles;
    for (Eigen::Index k = 0; k < st.atGain.eigenvalues.size(); ++k) {
        const std::complex<double> e = st.atGain.eigenvalues(k);
        poles << (std::abs(e.imag()) < 1e-9
                      ? g(e.real(), 4)
                      : QStringLiteral("%1%2%3i").arg(g(e.real(), 4),
                                                      e.imag() < 0 ? QStringLiteral("-") : QStringLiteral("+"),
                                                      g(std::abs(e.imag()), 4)));
    }
    printLine(QStringLiteral("Linearised at the steady state: eigenvalues %1 1/s; loop gain through the cut %2")
                  .arg(poles.join(QStringLiteral(", ")), g(st.atGain.loopGain, 3)));
    printLine(QStringLiteral("Design gain (slot opens by just the leakage): %1 V/V; this gain %2 V/V")
                  .arg(g(st.designGain, 5), g(r.scenario.params.amplifierGain, 5)));
    if (st.gainLimit) {
        printLine(QStringLiteral("Stability boundary of the gain: K_a = %1 V/V (%2 x the design gain)")
                      .arg(g(*st.gainLimit, 5), g(*st.gainLimit / st.designGain, 4)));
        if (r.check)
            printLine(
                QStringLiteral(
                    "  simulated: at %1 the feed settles at %2 m/s (predicted %3): %4; at %5 it ends at %6 m/s: %7")
                    .arg(g(r.check->belowGain, 5), g(r.check->below.feed.finalValue), g(r.check->predictedFeedMPerS))
                    .arg(r.check->belowSettles ? QStringLiteral("confirmed") : QStringLiteral("NOT confirmed"))
                    .arg(g(r.check->aboveGain, 5), g(r.check->above.feed.finalValue))
                    .arg(r.check->aboveRunsAway ? QStringLiteral("runs away to the fully open slot")
                                                : QStringLiteral("NOT running away")));
    } else {
        printLine(QStringLiteral("No gain destabilises the chain%1")
                      .arg(st.fullOpeningGain
                               ? QStringLiteral("; above K_a = %1 V/V (%2 x the design gain) the slot "
                                                "opens fully")
                                     .arg(g(*st.fullOpeningGain, 5), g(*st.fullOpeningGain / st.designGain, 4))
                               : QString()));
    }
}

void printText(const FeedReport& r) {
    const core::HydraulicFeedDerived d = core::deriveFeedQuantities(r.scenario.params);
    printLine(
        QStringLiteral("Hydraulic feed stabilisation (paper 003), preset %1: load %2 N, set feed %3 m/s, start %4")
            .arg(r.preset, g(r.scenario.finalLoadN()), g(r.scenario.params.setFeedMPerS))
            .arg(r.scenario.run.fromRest ? QStringLiteral("from rest") : QStringLiteral("running")));
    printLine(QStringLiteral("Cylinder F = %1 m², k0 = %2 1/m², T_c = %3 s, leakage %4 m³/s; T_k = %5 s, K_e = %6 N/A²")
                  .arg(g(d.pistonAreaM2), g(d.cylinderGainPerM2, 5), g(d.cylinderTimeConstantS, 3),
                       g(d.leakagePerNewtonM3PerS * r.scenario.finalLoadN()), g(d.magnetTimeConstantS, 3),
                       g(d.armatureGainNPerA2, 5)));
    printLine(QString());
    printLine(QStringLiteral("%1 %2 %3 %4 %5")
                  .arg(QString(), -24)
                  .arg(QStringLiteral("feed, m/s"), 12)
                  .arg(QStringLiteral("settling, s"), 11)
                  .arg(QStringLiteral("overshoot, %"), 12)
                  .arg(QStringLiteral("peak dev., m/s"), 14));
    printLine(metricsLine(QStringLiteral("without the regulator"), r.without));
    printLine(metricsLine(QStringLiteral("with the regulator"), r.with));
    printLine(QStringLiteral(
        "(settling: into 5 % of the largest deviation, the paper's t_c = 3T; + = not settled in the run)"));
    printLine(QString());
    printStability(r);
    if (!r.sensitivity.empty()) {
        printLine(QString());
        printLine(QStringLiteral("Steady feed change for -10 % / +10 % of a parameter (regulated | unregulated):"));
        for (std::size_t k = 0; k < std::min<std::size_t>(6, r.sensitivity.size()); ++k) {
            const core::FeedSensitivity& s = r.sensitivity[k];
            printLine(QStringLiteral("  %1 %2 % %3 %   | %4 % %5 %%6")
                          .arg(QString::fromStdString(s.name), -36)
                          .arg(QString::number(s.onMinusPct, 'f', 2), 8)
                          .arg(QString::number(s.onPlusPct, 'f', 2), 8)
                          .arg(QString::number(s.offMinusPct, 'f', 2), 8)
                          .arg(QString::number(s.offPlusPct, 'f', 2), 8)
                          .arg(s.fullyOpen ? QStringLiteral("  (slot fully open)") : QString()));
        }
    }
    if (r.sweepKind) {
        printLine(QString());
        printLine(QStringLiteral("Sweep of %1 (regulator on):").arg(QString::fromLatin1(core::toString(*r.sweepKind))));
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6")
                      .arg(QString::fromLatin1(core::toString(*r.sweepKind)), 9)
                      .arg(QStringLiteral("feed, m/s"), 12)
                      .arg(QStringLiteral("settling, s"), 11)
                      .arg(QStringLiteral("overshoot, %"), 12)
                      .arg(QStringLiteral("spool overshoot, %"), 18)
                      .arg(QStringLiteral("oscillates"), 10));
        for (const core::FeedSweepPoint& p : r.sweep)
            printLine(QStringLiteral("%1 %2 %3 %4 %5 %6%7")
                          .arg(g(p.value, 5), 9)
                          .arg(g(p.run.feed.finalValue), 12)
                          .arg(QString::number(p.run.feed.settlingS, 'f', 4) +
                                   (p.run.feed.settled ? QString() : QStringLiteral("+")),
                               11)
                          .arg(QString::number(p.run.feed.overshootPct, 'f', 2), 12)
                          .arg(QString::number(p.run.opening.overshootPct, 'f', 2), 18)
                          .arg(p.oscillates ? QStringLiteral("yes") : QStringLiteral("no"), 10)
                          .arg(p.stable ? (p.run.slotFullyOpen ? QStringLiteral("  slot fully open") : QString())
                                        : QStringLiteral("  unstable: runs away")));
    }
}

void writeCsv(const QString& path, const FeedReport& r) {
    QStringList labels;
    std::vector<const core::FeedRun*> runs;
    if (r.sweepKind) {
        for (const core::FeedSweepPoint& p : r.sweep) {
            labels << QStringLiteral("%1=%2").arg(QString::fromLatin1(core::toString(*r.sweepKind)), g(p.value, 6));
            runs.push_back(&p.run);
        }
    } else {
        labels << QStringLiteral("with regulator") << QStringLiteral("without regulator");
        runs = {&r.with, &r.without};
    }
    writeOutputFile(path, config::feedRunsCsv(labels, runs));
}

void addOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("preset"), QStringLiteral("Scenario preset or JSON file. Default: hydraulic-feed."),
                     QStringLiteral("NAME|FILE.json"), kDefaultPreset);
    parser.addOption(
        QStringLiteral("regulator"),
        QStringLiteral("Which run the top-level figures describe (both are always simulated). Default: on."),
        QStringLiteral("on|off"), QStringLiteral("on"));
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
    parser.addOption(QStringLiteral("sweep"), QStringLiteral("Step responses for a sweep of xi or of the gain."),
                     QStringLiteral("xi|gain"));
    parser.addOption(
        QStringLiteral("sweep-values"),
        QStringLiteral("The sweep's values, comma separated (default: xi 0.2 .. 2, gain 0 .. 2 x design)."),
        QStringLiteral("A,B,..."));
    parser.addOption(QStringLiteral("duration"), QStringLiteral("Simulated time, s (default: the preset's)."),
                     QStringLiteral("S"));
    parser.addOption(QStringLiteral("csv"),
                     QStringLiteral("Write the time series (both runs, or every sweep member) as CSV."),
                     QStringLiteral("FILE.csv"));
}

int runFeedStabilise(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("feed-stabilise"),
        QStringLiteral("Simulates the hydraulic feed drive of a finishing lathe with its feed stabiliser (paper 003): "
                       "sensor -> amplifier -> electromagnet -> spool flow regulator -> cylinder, integrated with an "
                       "adaptive Dormand-Prince stepper. Reports the steady feed, settling time and overshoot with "
                       "and without the regulator, the linearised chain's eigenvalues and the gain's stability "
                       "boundary, the parameters' sensitivity, and sweeps of xi or of the gain."));
    addOptions(parser);
    parser.parse(arguments);
    FeedReport r;
    r.preset = parser.value(QStringLiteral("preset"));
    r.regulatorOn = parser.choice(QStringLiteral("regulator"), {QStringLiteral("on"), QStringLiteral("off")}) ==
                    QStringLiteral("on");
    if (parser.isSet(QStringLiteral("sweep")))
        r.sweepKind = core::feedSweepKindFromString(
            parser.choice(QStringLiteral("sweep"), {QStringLiteral("xi"), QStringLiteral("gain")}).toStdString());
    r.scenario = scenarioFrom(parser, r.preset);
    r.with = core::runFeedScenario(r.scenario, true);
    r.without = core::runFeedScenario(r.scenario, false);
    const double load = r.scenario.finalLoadN();
    if (load > 0.0) {
        try {
            r.stability = core::analyseStability(r.scenario.params, load);
        } catch (const std::invalid_argument& e) {
            r.stabilityNote = QString::fromStdString(e.what());  // no design point: the slot cannot make it up
        }
        if (r.stability && r.stability->gainLimit)
            r.check = core::crossCheckGainLimit(r.scenario, *r.stability->gainLimit);
        r.sensitivity = core::feedSensitivity(r.scenario.params, load);
    } else {
        r.stabilityNote = QStringLiteral("the scenario ends without load: nothing to regulate");
    }
    if (r.sweepKind) {
        const std::vector<double> values = sweepValues(parser, *r.sweepKind, r.scenario);
        r.sweep = asUsage(QStringLiteral("--sweep-values"),
                          [&] { return core::sweepFeed(r.scenario, *r.sweepKind, values); });
    }
    if (parser.isSet(QStringLiteral("csv"))) writeCsv(parser.required(QStringLiteral("csv")), r);
    if (parser.json())
        printJson(toJson(r));
    else
        printText(r);
    return kExitOk;
}

}  // namespace

Command makeFeedStabiliseCommand() {
    return {QStringLiteral("feed-stabilise"),
            QStringLiteral(
                "hydraulic feed stabilisation under a changing cutting force (paper 003), sweeps of xi and gain"),
            runFeedStabilise};
}

}  // namespace tt::cli
