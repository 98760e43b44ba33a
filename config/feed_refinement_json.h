#pragma once

#include <QJsonObject>
#include <QString>

#include "config/deformation_model_config.h"
#include "core/control/feed_refinement_design.h"
#include "core/sim/shaft/feed_refinement.h"
#include "core/sim/shaft/feed_schedule_check.h"

namespace tt::config {

/// A scheduled pass machined on the simulator: {"max_deviation_pct", "worst_z", "worst_y_um",
/// "within_10_pct", "fmax_excess_pct", "fmax_worst_z", "fmin_shortfall_pct"}.
QJsonObject feedScheduleCheckToJson(const core::FeedScheduleCheck& check);

/// A round's plan: {"depth_mm", "bars": [{"f", "z": [..]}], "bar_count", "gauge_points", "sigma_um",
/// "margin_um", "target_half_width_um", "half_width_before_um", "half_width_after_um",
/// "measurements_before", "feed_levels_before"}.
QJsonObject refinementProposalToJson(const core::RefinementProposal& plan);

/// The refinement: {"rounds_run", "max_rounds", "bars", "gauge_points", "within_10_pct", "advice"?,
/// "initial": {"max_deviation_pct", "worst_z", "within_10_pct"},
/// "rounds": [{"round", "plan": {..}, "measurements", "model"?: {"term_set", "terms", "n", "r2",
/// "sigma_resid_um", "two_sigma_um"}, "model_deviation_pct"?, "verify"?: {..}, "problem"?}]}.
QJsonObject feedRefinementToJson(const core::FeedRefinement& refinement, int maxRounds);

/// The model file of a refinement's local model: the fit's statistics, the set-up, seed and job of the
/// model it refines, and as source "<base source> + N targeted bars at a = A mm".
DeformationModelFile refinedModelFile(const core::DeformationFit& fit, const DeformationModelFile& base, int bars);

}  // namespace tt::config
