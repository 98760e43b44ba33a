#include "ui/process/corner_plots.h"

#include <QColor>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <limits>

#include "plot/chart.h"

namespace tt::ui::corner_plots {

namespace {

const QColor kProgrammed(30, 30, 30);
const QColor kWithout(198, 40, 40);
const QColor kWith(46, 125, 50);
const QColor kPulse(21, 101, 192);
const QColor kBand(240, 160, 48);
const QColor kThreshold(120, 120, 120);

std::vector<double> scaled(const std::vector<double>& v, double factor) {
    std::vector<double> out;
    out.reserve(v.size());
    for (double x : v)
        out.push_back(x * factor);
    return out;
}

double largest(const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

}  // namespace

void showPaths(plot::Chart& chart, const core::CornerRun& without, const core::CornerRun& with, bool zoom) {
    chart.setTitle(QCoreApplication::translate("CornerPlots", "Path near the corner"));
    chart.setAxisTitles(QCoreApplication::translate("CornerPlots", "Z, mm"),
                        QCoreApplication::translate("CornerPlots", "X, mm"));
    const core::CornerTrace& w = without.trace;
    chart.setSeries(QStringLiteral("programmed"), QCoreApplication::translate("CornerPlots", "Programmed"),
                    w.programmedZMm, w.programmedXMm, kProgrammed);
    chart.setSeries(QStringLiteral("without"), QCoreApplication::translate("CornerPlots", "Without pulse"), w.zMm,
                    w.xMm, kWithout);
    chart.setSeries(QStringLiteral("with"), QCoreApplication::translate("CornerPlots", "With pulse"), with.trace.zMm,
                    with.trace.xMm, kWith);
    chart.setLegendBelow(1);
    chart.setXTickCount(4);
    chart.rescale(false);
    chart.refresh();
    if (!zoom) return;
    // Four times the largest contour error around the corner (at least 0.1 mm) in both directions.
    const double half = std::max(0.1, 4.0 * std::max(largest(w.errorMm), largest(with.trace.errorMm)));
    chart.setXRange(-half, half);
    chart.setYRange(-half, half);
    chart.refresh();
}

void showErrors(plot::Chart& chart, const core::CornerRun& without, const core::CornerRun& with) {
    chart.setTitle(QCoreApplication::translate("CornerPlots", "Contour error"));
    chart.setAxisTitles(QCoreApplication::translate("CornerPlots", "Time, ms"),
                        QCoreApplication::translate("CornerPlots", "Error, µm"));
    const std::vector<double> t = scaled(without.trace.timeS, 1e3);
    const std::vector<double> e0 = scaled(without.trace.errorMm, 1e3);
    const std::vector<double> e1 = scaled(with.trace.errorMm, 1e3);
    const double top = std::max(largest(e0), largest(e1)) * 1.05;
    chart.setBand(QStringLiteral("interval"), QCoreApplication::translate("CornerPlots", "Control interval"),
                  {without.intervalStartS * 1e3, without.intervalEndS * 1e3}, {0.0, 0.0}, {top, top}, kBand);
    chart.setSeries(QStringLiteral("without"), QCoreApplication::translate("CornerPlots", "Without pulse"), t, e0,
                    kWithout);
    chart.setSeries(QStringLiteral("with"), QCoreApplication::translate("CornerPlots", "With pulse"),
                    scaled(with.trace.timeS, 1e3), e1, kWith);
    chart.setLegendBelow(2);
    chart.rescale(true);
    chart.refresh();
}

void showPulse(plot::Chart& chart, const core::CornerRun& with, core::FeedAxis pulseAxis) {
    chart.setTitle(pulseAxis == core::FeedAxis::X
                       ? QCoreApplication::translate("CornerPlots", "Corrective pulse on X")
                       : QCoreApplication::translate("CornerPlots", "Corrective pulse on Z"));
    chart.setAxisTitles(QCoreApplication::translate("CornerPlots", "Time, ms"),
                        QCoreApplication::translate("CornerPlots", "Pulse, V"));
    chart.setSeries(QStringLiteral("pulse"), QString(), scaled(with.trace.timeS, 1e3), with.trace.pulseV, kPulse,
                    plot::Chart::Style::Steps);
    chart.setYTickCount(3);
    chart.rescale(true);
    chart.refresh();
}

void showTraining(plot::Chart& chart, const std::vector<double>& trainingLoss,
                  const std::vector<double>& validationLoss, double outputScaleV) {
    chart.setTitle(QCoreApplication::translate("CornerPlots", "Network training"));
    chart.setAxisTitles(QCoreApplication::translate("CornerPlots", "Epoch"),
                        QCoreApplication::translate("CornerPlots", "RMS amplitude error, mV"));
    const auto toMv = [outputScaleV](const std::vector<double>& loss) {
        std::vector<double> out;
        out.reserve(loss.size());
        for (double l : loss)
            out.push_back(std::sqrt(2.0 * std::max(0.0, l)) * outputScaleV * 1e3);
        return out;
    };
    std::vector<double> epochs(trainingLoss.size());
    for (std::size_t i = 0; i < epochs.size(); ++i)
        epochs[i] = static_cast<double>(i + 1);
    chart.setSeries(QStringLiteral("training"), QCoreApplication::translate("CornerPlots", "Training moves"), epochs,
                    toMv(trainingLoss), kWith);
    chart.setSeries(
        QStringLiteral("validation"), QCoreApplication::translate("CornerPlots", "Validation moves"),
        std::vector<double>(epochs.begin(), epochs.begin() + static_cast<std::ptrdiff_t>(validationLoss.size())),
        toMv(validationLoss), kPulse);
    chart.setLegendBelow(2);
    chart.rescale(true);
    // The first epochs start far off; show the part where the curves separate.
    if (trainingLoss.size() > 20) {
        const std::vector<double> v = toMv(validationLoss);
        chart.setYRange(0.0, 3.0 * *std::min_element(v.begin(), v.end()) + 5.0);
    }
    chart.refresh();
}

void showDrift(plot::Chart& chart, const core::CornerWorkResult& run, double thresholdFraction, int windowCorners) {
    chart.setTitle(QCoreApplication::translate("CornerPlots", "Drift monitor"));
    chart.setAxisTitles(QCoreApplication::translate("CornerPlots", "Corner"),
                        QCoreApplication::translate("CornerPlots", "Measured − predicted cost, %"));
    std::vector<double> corners, difference, retrainX, retrainY, refusedX, refusedY;
    const int window = run.checks.empty() ? 0 : windowCorners;
    for (std::size_t i = 0; i < run.checks.size(); ++i) {
        corners.push_back(static_cast<double>(i + 1));
        // Until the window is full again (at the start, after a retraining) there is no verdict: a gap.
        difference.push_back(run.checks[i].corners < window ? std::numeric_limits<double>::quiet_NaN()
                                                            : 100.0 * run.checks[i].differenceFraction);
    }
    const double t = 100.0 * thresholdFraction;
    // A difference beyond the plotted ±3 thresholds (a drift of the velocity gain: +100 % and more) is
    // marked at the edge; the text beside the chart gives its value.
    for (const core::CornerRetrainEvent& e : run.retrains) {
        const double d = 100.0 * run.checks[static_cast<std::size_t>(e.move)].differenceFraction;
        (e.verdict.accepted ? retrainX : refusedX).push_back(e.move + 1.0);
        (e.verdict.accepted ? retrainY : refusedY).push_back(std::clamp(d, -2.9 * t, 2.9 * t));
    }
    const double last = std::max(1.0, static_cast<double>(run.checks.size()));
    chart.setBand(QStringLiteral("threshold"), QCoreApplication::translate("CornerPlots", "Within the threshold"),
                  {1.0, last}, {-t, -t}, {t, t}, kThreshold);
    chart.setSeries(QStringLiteral("difference"),
                    QCoreApplication::translate("CornerPlots", "Last %1 corners").arg(windowCorners), corners,
                    difference, kPulse, plot::Chart::Style::LineAndPoints);
    chart.setSeries(QStringLiteral("retrained"), QCoreApplication::translate("CornerPlots", "Retrained"), retrainX,
                    retrainY, kWithout, plot::Chart::Style::Points);
    chart.setSeries(QStringLiteral("refused"), QCoreApplication::translate("CornerPlots", "Retraining refused"),
                    refusedX, refusedY, kBand, plot::Chart::Style::Points);
    chart.setLegendBelow(2);  // two rows: the Russian names do not fit in one
    chart.rescale(true);
    chart.setYRange(-3.0 * t, 3.0 * t);
    chart.refresh();
}

}  // namespace tt::ui::corner_plots
