#pragma once

#include <vector>

#include "core/control/corrective_net.h"
#include "core/sim/feed_drives/corner_work_run.h"

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

/// What the Corner tool draws; the texts are translated in the "CornerPlots" context.
namespace corner_plots {

/// The programmed path and the simulated tool paths without and with the pulse in the Z–X plane;
/// `zoom`: only the neighbourhood of the corner, where the paths part.
void showPaths(plot::Chart& chart, const core::CornerRun& without, const core::CornerRun& with, bool zoom);
/// Contour error over time without and with the pulse, µm, and the control interval as a band.
void showErrors(plot::Chart& chart, const core::CornerRun& without, const core::CornerRun& with);
/// The corrective pulse over time, V.
void showPulse(plot::Chart& chart, const core::CornerRun& with, core::FeedAxis pulseAxis);
/// RMS amplitude error per epoch on the training and the validation moves, mV (loss in normalised
/// units → √(2 L) × output scale); `outputScaleV` of the network being trained.
void showTraining(plot::Chart& chart, const std::vector<double>& trainingLoss,
                  const std::vector<double>& validationLoss, double outputScaleV);
/// The drift monitor over a run of corners: measured minus predicted cost in % of the prediction,
/// the threshold, and where the network was retrained or a retrained network refused (marked at the
/// chart's edge when beyond it); no point while fewer than `windowCorners` corners are in the window
/// (at the start and after a retraining).
void showDrift(plot::Chart& chart, const core::CornerWorkResult& run, double thresholdFraction, int windowCorners);

}  // namespace corner_plots

}  // namespace tt::ui
