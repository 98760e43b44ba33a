// The text output of `trueturn feed-stabilise` (cmd_feed_stabilise_output.h).
#include <QStringList>
#include <algorithm>
#include <cmath>

#include "app/cli/cmd_feed_stabilise_output.h"
#include "app/cli/command_parser.h"

namespace tt::cli {

namespace {

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

/// A feed, m/s: the integrator's 1e-19 of a stalled carriage printed as 0.
QString feed(double v) {
    return g(std::abs(v) < 1e-12 ? 0.0 : v);
}

/// A percentage with 2 decimals, without "-0.00".
QString pct(double v) {
    const double rounded = std::round(v * 100.0) / 100.0;
    return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', 2);
}

QString label(core::FeedRegulator r) {
    switch (r) {
        case core::FeedRegulator::Off:
            return QStringLiteral("without the regulator");
        case core::FeedRegulator::FeedForward:
            return QStringLiteral("feed-forward (paper's)");
        case core::FeedRegulator::Feedback:
            return QStringLiteral("feedback");
    }
    return {};
}

QString metricsLine(const QString& what, const core::FeedRun& run) {
    return QStringLiteral("%1 %2 %3 %4 %5 %6")
        .arg(what, -26)
        .arg(feed(run.feed.finalValue), 12)
        .arg(pct(run.deviationPct), 9)
        .arg(QString::number(run.feed.settlingS, 'f', 4) + (run.feed.settled ? QString() : QStringLiteral("+")), 11)
        .arg(QString::number(run.feed.overshootPct, 'f', 2), 12)
        .arg(g(run.feed.peakDeviation, 3), 14);
}

void printRuns(const FeedReport& r) {
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6")
                  .arg(QString(), -26)
                  .arg(QStringLiteral("feed, m/s"), 12)
                  .arg(QStringLiteral("dev., %"), 9)
                  .arg(QStringLiteral("settling, s"), 11)
                  .arg(QStringLiteral("overshoot, %"), 12)
                  .arg(QStringLiteral("peak dev., m/s"), 14));
    for (core::FeedRegulator reg :
         {core::FeedRegulator::Off, core::FeedRegulator::FeedForward, core::FeedRegulator::Feedback})
        printLine(metricsLine(label(reg) + (reg == r.regulator ? QStringLiteral(" *") : QString()), r.run(reg)));
    printLine(
        QStringLiteral("(* = --regulator; settling: into 5 % of the largest deviation, the paper's t_c = 3T; + = "
                       "not settled in the run)"));
    const core::FeedRun& chosen = r.chosen();
    printLine(QStringLiteral("Held (%1): largest deviation %2 % at %3 s, leaving out 3 T_c = %4 s after each load "
                             "change: %5 the band of +-%6 %")
                  .arg(label(r.regulator), QString::number(chosen.hold.largestDeviationPct, 'f', 2), g(chosen.hold.atS),
                       g(chosen.hold.excludedS, 3),
                       chosen.hold.withinBand ? QStringLiteral("within") : QStringLiteral("OUTSIDE"),
                       g(chosen.hold.bandPct)));
    for (const core::FeedWarning& w : chosen.warnings)
        printLine(QStringLiteral("Warning: %1").arg(feedWarningText(w, chosen.setFeedMPerS, r.scenario.run.bandPct)));
}

QString optionalText(const std::optional<double>& v, int precision, const QString& none) {
    return v ? g(*v, precision) : none;
}

void printFeedback(const FeedReport& r) {
    const core::FeedFeedbackDesign& d = r.feedbackDesign;
    const core::ContinuousMargins& m = d.margins;
    printLine(QStringLiteral("Feedback: PID on the measured feed, K_p = %1 s (m of opening per m/s), T_i = %2 s, "
                             "T_d = %3 s, T_f = %4 s, through a square-root characteriser")
                  .arg(g(d.gainS), g(d.integralTimeS, 4), g(d.leadTimeS, 4), g(d.filterTimeS, 4)));
    printLine(QStringLiteral("Margins of the linearised loop (eqs. 17 and 22): gain %1 (%2 dB) at %3 rad/s, phase "
                             "%4 deg at %5 rad/s, delay %6 s; closed loop %7")
                  .arg(optionalText(m.gainMargin, 4, QStringLiteral("infinite")),
                       optionalText(m.gainMarginDb(), 3, QStringLiteral("-")),
                       optionalText(m.phaseCrossoverRadPerS, 4, QStringLiteral("-")),
                       optionalText(m.phaseMarginDeg, 4, QStringLiteral("infinite")),
                       optionalText(m.gainCrossoverRadPerS, 4, QStringLiteral("-")),
                       optionalText(m.delayMarginS, 3, QStringLiteral("-")),
                       m.closedLoopStable ? QStringLiteral("stable") : QStringLiteral("UNSTABLE")));
}

void printStability(const FeedReport& r) {
    if (!r.stability) {
        printLine(QStringLiteral("Feed-forward gain analysis: not made, %1.").arg(r.stabilityNote));
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
        return;
    }
    printLine(QStringLiteral("No gain destabilises the chain%1")
                  .arg(st.fullOpeningGain
                           ? QStringLiteral("; above K_a = %1 V/V (%2 x the design gain) the slot "
                                            "opens fully")
                                 .arg(g(*st.fullOpeningGain, 5), g(*st.fullOpeningGain / st.designGain, 4))
                           : QString()));
}

void printSensitivity(const FeedReport& r) {
    if (r.sensitivity.empty()) return;
    printLine(QString());
    printLine(QStringLiteral("Steady feed change for -10 % / +10 % of a parameter (%1 | unregulated):")
                  .arg(label(r.compared())));
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

void printSweep(const FeedReport& r) {
    const QString name = QString::fromLatin1(core::toString(*r.sweepKind));
    printLine(QString());
    printLine(
        QStringLiteral("Sweep of %1 (%2%3):")
            .arg(name, label(r.compared()),
                 r.compared() == core::FeedRegulator::Feedback && *r.sweepKind == core::FeedSweepKind::AmplifierGain
                     ? QStringLiteral("; the gain is a factor on the designed K_p")
                     : QString()));
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6")
                  .arg(name, 9)
                  .arg(QStringLiteral("feed, m/s"), 12)
                  .arg(QStringLiteral("settling, s"), 11)
                  .arg(QStringLiteral("overshoot, %"), 12)
                  .arg(QStringLiteral("spool overshoot, %"), 18)
                  .arg(QStringLiteral("oscillates"), 10));
    for (const core::FeedSweepPoint& p : r.sweep)
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6%7%8")
                      .arg(g(p.value, 5), 9)
                      .arg(g(p.run.feed.finalValue), 12)
                      .arg(QString::number(p.run.feed.settlingS, 'f', 4) +
                               (p.run.feed.settled ? QString() : QStringLiteral("+")),
                           11)
                      .arg(QString::number(p.run.feed.overshootPct, 'f', 2), 12)
                      .arg(QString::number(p.run.opening.overshootPct, 'f', 2), 18)
                      .arg(p.oscillates ? QStringLiteral("yes") : QStringLiteral("no"), 10)
                      .arg(p.feedback
                               ? QStringLiteral("  margins %1 / %2 deg")
                                     .arg(p.feedback->margins.gainMargin ? g(*p.feedback->margins.gainMargin, 3)
                                                                         : QStringLiteral("inf"),
                                          p.feedback->margins.phaseMarginDeg ? g(*p.feedback->margins.phaseMarginDeg, 3)
                                                                             : QStringLiteral("inf"))
                               : QString())
                      .arg(p.stable ? (p.run.slotFullyOpen ? QStringLiteral("  slot fully open") : QString())
                                    : QStringLiteral("  unstable")));
}

void printLoadSweep(const FeedReport& r) {
    const double band = r.scenario.run.bandPct;
    const double threeTc = 3.0 * core::deriveFeedQuantities(r.scenario.params).cylinderTimeConstantS;
    printLine(QString());
    printLine(QStringLiteral("Load sweep: one step to each load; steady feed and its deviation from the set feed %1 "
                             "m/s (band +-%2 %); settling and warnings of %3 (3 T_c = %4 s):")
                  .arg(g(r.scenario.params.setFeedMPerS), g(band), label(r.compared()), g(threeTc, 3)));
    printLine(QStringLiteral("%1 %2 %3 %4 %5 %6  %7")
                  .arg(QStringLiteral("load, N"), 8)
                  .arg(QStringLiteral("unregulated"), 12)
                  .arg(QStringLiteral("feed-forward"), 12)
                  .arg(QStringLiteral("dev., %"), 8)
                  .arg(QStringLiteral("feedback"), 12)
                  .arg(QStringLiteral("dev., %"), 8)
                  .arg(QStringLiteral("settling, s / within / warnings")));
    for (const core::FeedLoadPoint& p : r.loads) {
        const core::FeedRun& run = p.of(r.compared());
        QStringList warnings;
        for (const core::FeedWarning& w : run.warnings)
            warnings << QString::fromLatin1(core::toString(w.kind));
        printLine(QStringLiteral("%1 %2 %3 %4 %5 %6  %7 %8 %9")
                      .arg(g(p.loadN), 8)
                      .arg(feed(p.off.feed.finalValue), 12)
                      .arg(feed(p.feedForward.feed.finalValue), 12)
                      .arg(pct(p.feedForward.deviationPct), 8)
                      .arg(feed(p.feedback.feed.finalValue), 12)
                      .arg(pct(p.feedback.deviationPct), 8)
                      .arg(QString::number(run.feed.settlingS, 'f', 4))
                      .arg(std::abs(run.deviationPct) <= band ? QStringLiteral("yes") : QStringLiteral("NO"))
                      .arg(warnings.join(QStringLiteral(", "))));
    }
}

}  // namespace

void printFeedReport(const FeedReport& r) {
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
    printRuns(r);
    printLine(QString());
    printFeedback(r);
    printStability(r);
    printSensitivity(r);
    if (r.sweepKind) printSweep(r);
    if (r.loadSweep) printLoadSweep(r);
}

}  // namespace tt::cli
