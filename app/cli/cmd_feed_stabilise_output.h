#pragma once

#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/sim/hydraulic/feed_study.h"

namespace tt::cli {

/// Everything `trueturn feed-stabilise` computes (paper 003): the scenario run without a regulator, with the
/// paper's feed-forward and with the feedback, the feedback's design and margins, the feed-forward's gain
/// analysis, the sensitivity, and a sweep of xi, the gain or the load.
struct FeedReport {
    QString preset;
    core::FeedScenario scenario;
    core::FeedRegulator regulator = core::FeedRegulator::Feedback;  ///< the one the top-level figures describe
    core::FeedRun off;
    core::FeedRun feedForward;
    core::FeedRun feedback;
    core::FeedFeedbackDesign feedbackDesign;
    std::optional<core::FeedStability> stability;  ///< the feed-forward's gain analysis (--regulator feedforward)
    QString stabilityNote;                         ///< why there is no such analysis
    std::optional<core::FeedBoundaryCheck> check;
    std::vector<core::FeedSensitivity> sensitivity;
    std::optional<core::FeedSweepKind> sweepKind;
    std::vector<core::FeedSweepPoint> sweep;
    bool loadSweep = false;
    std::vector<core::FeedLoadPoint> loads;

    /// The run with the chosen regulator.
    const core::FeedRun& chosen() const { return run(regulator); }
    /// The regulated run the report compares with the unregulated one: the chosen regulator, or the
    /// default (feedback) when the regulator is off.
    core::FeedRegulator compared() const {
        return regulator == core::FeedRegulator::Off ? core::FeedRegulator::Feedback : regulator;
    }
    const core::FeedRun& run(core::FeedRegulator r) const {
        return r == core::FeedRegulator::Off ? off : r == core::FeedRegulator::FeedForward ? feedForward : feedback;
    }
};

/// The report as the command's JSON (fields documented in README's command table and docs/DECISIONS).
QJsonObject feedReportJson(const FeedReport& report);
/// Prints the report as text on stdout.
void printFeedReport(const FeedReport& report);
/// Writes the curves as CSV: every sweep member, or the regulated and the unregulated run.
void writeFeedCsv(const QString& path, const FeedReport& report);
/// A warning in the user's words, e.g. "the carriage stalled on its stop from 0.045 s to 0.4 s ...".
QString feedWarningText(const core::FeedWarning& warning, double setFeedMPerS, double bandPct);

}  // namespace tt::cli
