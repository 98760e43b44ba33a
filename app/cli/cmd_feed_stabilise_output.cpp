#include "app/cli/cmd_feed_stabilise_output.h"

#include <QJsonArray>
#include <QStringList>
#include <algorithm>
#include <cmath>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "config/hydraulic_feed_config.h"
#include "config/hydraulic_feed_csv.h"

namespace tt::cli {

namespace {

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

QJsonValue optional(const std::optional<double>& v) {
    return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
}

QString regulatorName(core::FeedRegulator r) {
    return QString::fromLatin1(core::toString(r));
}

QJsonArray warningsJson(const core::FeedRun& run, double bandPct) {
    QJsonArray out;
    for (const core::FeedWarning& w : run.warnings)
        out.append(QJsonObject{{QStringLiteral("kind"), QString::fromLatin1(core::toString(w.kind))},
                               {QStringLiteral("from_s"), w.fromS},
                               {QStringLiteral("to_s"), w.toS},
                               {QStringLiteral("duration_s"), w.durationS},
                               {QStringLiteral("value"), w.value},
                               {QStringLiteral("message"), feedWarningText(w, run.setFeedMPerS, bandPct)}});
    return out;
}

QJsonObject holdJson(const core::FeedHold& h) {
    return {{QStringLiteral("band_pct"), h.bandPct},
            {QStringLiteral("excluded_after_each_change_s"), h.excludedS},
            {QStringLiteral("largest_deviation_pct"), h.largestDeviationPct},
            {QStringLiteral("at_s"), h.atS},
            {QStringLiteral("within_band"), h.withinBand}};
}

QJsonObject metricsJson(const core::FeedRun& run, double bandPct) {
    return {{QStringLiteral("steady_feed_m_s"), run.feed.finalValue},
            {QStringLiteral("deviation_pct"), run.deviationPct},
            {QStringLiteral("within_band"), std::abs(run.deviationPct) <= bandPct},
            {QStringLiteral("settling_s"), run.feed.settlingS},
            {QStringLiteral("overshoot_pct"), run.feed.overshootPct},
            {QStringLiteral("peak_deviation_m_s"), run.feed.peakDeviation},
            {QStringLiteral("spool_overshoot_pct"), run.opening.overshootPct},
            {QStringLiteral("settled"), run.feed.settled},
            {QStringLiteral("slot_fully_open"), run.slotFullyOpen},
            {QStringLiteral("hold"), holdJson(run.hold)},
            {QStringLiteral("warnings"), warningsJson(run, bandPct)}};
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

QJsonArray polesJson(const std::vector<std::complex<double>>& poles) {
    QJsonArray out;
    for (const std::complex<double>& p : poles)
        out.append(QJsonObject{{QStringLiteral("re"), p.real()}, {QStringLiteral("im"), p.imag()}});
    return out;
}

QJsonObject marginsJson(const core::ContinuousMargins& m) {
    return {{QStringLiteral("gain_margin"), optional(m.gainMargin)},
            {QStringLiteral("gain_margin_db"), optional(m.gainMarginDb())},
            {QStringLiteral("phase_crossover_rad_s"), optional(m.phaseCrossoverRadPerS)},
            {QStringLiteral("phase_margin_deg"), optional(m.phaseMarginDeg)},
            {QStringLiteral("gain_crossover_rad_s"), optional(m.gainCrossoverRadPerS)},
            {QStringLiteral("delay_margin_s"), optional(m.delayMarginS)},
            {QStringLiteral("closed_loop_stable"), m.closedLoopStable},
            {QStringLiteral("closed_loop_poles_per_s"), polesJson(m.closedLoopPoles)}};
}

QJsonObject transferJson(const core::RationalTransfer& t) {
    QJsonArray num;
    QJsonArray den;
    for (double c : t.numerator)
        num.append(c);
    for (double c : t.denominator)
        den.append(c);
    return {{QStringLiteral("numerator"), num}, {QStringLiteral("denominator"), den}};
}

QJsonObject feedbackJson(const core::FeedFeedbackDesign& d) {
    return {{QStringLiteral("gain_s"), d.gainS},
            {QStringLiteral("integral_time_s"), d.integralTimeS},
            {QStringLiteral("lead_time_s"), d.leadTimeS},
            {QStringLiteral("filter_time_s"), d.filterTimeS},
            {QStringLiteral("tracking_time_s"), d.trackingTimeS},
            {QStringLiteral("target_phase_margin_deg"), d.targets.phaseMarginDeg},
            {QStringLiteral("min_gain_margin"), d.targets.minGainMargin},
            {QStringLiteral("plant"), transferJson(d.plant)},
            {QStringLiteral("controller"), transferJson(d.controller)}};
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

/// The sweep's value column: "xi", "gain" (K_a of the feed-forward) or "gain_factor" (on the feedback's K_p).
QString sweepKey(const FeedReport& r) {
    if (*r.sweepKind == core::FeedSweepKind::AmplifierGain && r.compared() == core::FeedRegulator::Feedback)
        return QStringLiteral("gain_factor");
    return QString::fromLatin1(core::toString(*r.sweepKind));
}

QJsonArray sweepJson(const FeedReport& r) {
    QJsonArray out;
    const double band = r.scenario.run.bandPct;
    for (const core::FeedSweepPoint& p : r.sweep) {
        QJsonObject row = metricsJson(p.run, band);
        row.insert(sweepKey(r), p.value);
        row.insert(QStringLiteral("oscillates"), p.oscillates);
        row.insert(QStringLiteral("stable"), p.stable);
        if (p.feedback) row.insert(QStringLiteral("margins"), marginsJson(p.feedback->margins));
        out.append(row);
    }
    return out;
}

double threeTc(const FeedReport& r) {
    return 3.0 * core::deriveFeedQuantities(r.scenario.params).cylinderTimeConstantS;
}

QJsonObject loadSweepJson(const FeedReport& r) {
    QJsonArray rows;
    const double band = r.scenario.run.bandPct;
    bool allWithin = true;
    double largest = 0.0;
    for (const core::FeedLoadPoint& p : r.loads) {
        const core::FeedRun& run = p.of(r.compared());
        QJsonObject row = metricsJson(run, band);
        row.insert(QStringLiteral("load_n"), p.loadN);
        row.insert(QStringLiteral("settling_within_3tc"), run.feed.settlingS <= threeTc(r));
        row.insert(QStringLiteral("feedforward_steady_feed_m_s"), p.feedForward.feed.finalValue);
        row.insert(QStringLiteral("feedforward_deviation_pct"), p.feedForward.deviationPct);
        row.insert(QStringLiteral("feedback_steady_feed_m_s"), p.feedback.feed.finalValue);
        row.insert(QStringLiteral("feedback_deviation_pct"), p.feedback.deviationPct);
        row.insert(QStringLiteral("unregulated_steady_feed_m_s"), p.off.feed.finalValue);
        allWithin = allWithin && std::abs(run.deviationPct) <= band;
        if (std::abs(run.deviationPct) > std::abs(largest)) largest = run.deviationPct;
        rows.append(row);
    }
    return {{QStringLiteral("regulator"), regulatorName(r.compared())},
            {QStringLiteral("band_pct"), band},
            {QStringLiteral("three_tc_s"), threeTc(r)},
            {QStringLiteral("all_within_band"), allWithin},
            {QStringLiteral("largest_deviation_pct"), largest},
            {QStringLiteral("rows"), rows}};
}

}  // namespace

QString feedWarningText(const core::FeedWarning& w, double setFeedMPerS, double bandPct) {
    const QString span = QStringLiteral("from %1 s to %2 s (%3 s in all)").arg(g(w.fromS), g(w.toS), g(w.durationS, 3));
    switch (w.kind) {
        case core::FeedWarningKind::CarriageStalled:
            return QStringLiteral("the carriage stalled on its stop %1: the flow could not make up the load's leakage")
                .arg(span);
        case core::FeedWarningKind::SlotFullyOpen:
            return QStringLiteral(
                       "the slot was fully open (the spool on its stop) %1: the regulator could give no more flow")
                .arg(span);
        case core::FeedWarningKind::SlotShut:
            return QStringLiteral("the feedback asked for less than a shut slot %1: it could take no flow away")
                .arg(span);
        case core::FeedWarningKind::FeedOffSet:
            return QStringLiteral("the feed ends %1 % from the set feed %2 m/s, outside the band of +-%3 %")
                .arg(QString::number(w.value, 'f', 2), g(setFeedMPerS), g(bandPct));
    }
    return {};
}

QJsonObject feedReportJson(const FeedReport& r) {
    const double band = r.scenario.run.bandPct;
    QJsonObject out = metricsJson(r.chosen(), band);
    out.insert(QStringLiteral("preset"), r.preset);
    out.insert(QStringLiteral("regulator"), regulatorName(r.regulator));
    out.insert(QStringLiteral("start"), r.scenario.run.fromRest ? QStringLiteral("rest") : QStringLiteral("running"));
    out.insert(QStringLiteral("load_n"), r.scenario.finalLoadN());
    out.insert(QStringLiteral("set_feed_m_s"), r.scenario.params.setFeedMPerS);
    out.insert(QStringLiteral("with_regulator"), metricsJson(r.run(r.compared()), band));
    out.insert(QStringLiteral("without_regulator"), metricsJson(r.off, band));
    out.insert(QStringLiteral("feedforward"), metricsJson(r.feedForward, band));
    out.insert(QStringLiteral("feedback"), metricsJson(r.feedback, band));
    out.insert(QStringLiteral("feedback_design"), feedbackJson(r.feedbackDesign));
    out.insert(QStringLiteral("margins"), marginsJson(r.feedbackDesign.margins));
    out.insert(QStringLiteral("parameters"), config::hydraulicFeedParamsToJson(r.scenario.params));
    out.insert(QStringLiteral("derived"), derivedJson(r.scenario));
    out.insert(QStringLiteral("stability"),
               r.stability ? QJsonValue(stabilityJson(*r.stability, r.check)) : QJsonValue(QJsonValue::Null));
    if (!r.stabilityNote.isEmpty()) out.insert(QStringLiteral("stability_note"), r.stabilityNote);
    out.insert(QStringLiteral("sensitivity"), sensitivityJson(r.sensitivity));
    if (r.sweepKind) {
        out.insert(QStringLiteral("sweep_of"), QString::fromLatin1(core::toString(*r.sweepKind)));
        out.insert(QStringLiteral("sweep"), sweepJson(r));
    }
    if (r.loadSweep) {
        out.insert(QStringLiteral("sweep_of"), QStringLiteral("load"));
        out.insert(QStringLiteral("load_sweep"), loadSweepJson(r));
    }
    return out;
}

void writeFeedCsv(const QString& path, const FeedReport& r) {
    QStringList labels;
    std::vector<const core::FeedRun*> runs;
    if (r.sweepKind) {
        for (const core::FeedSweepPoint& p : r.sweep) {
            labels << QStringLiteral("%1=%2").arg(sweepKey(r), g(p.value, 6));
            runs.push_back(&p.run);
        }
    } else if (r.loadSweep) {
        for (const core::FeedLoadPoint& p : r.loads) {
            labels << QStringLiteral("load=%1").arg(g(p.loadN, 6));
            runs.push_back(&p.of(r.compared()));
        }
    } else {
        labels << QStringLiteral("with regulator") << QStringLiteral("without regulator");
        runs = {&r.run(r.compared()), &r.off};
    }
    writeOutputFile(path, config::feedRunsCsv(labels, runs));
}

}  // namespace tt::cli
