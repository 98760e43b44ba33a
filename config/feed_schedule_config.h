#pragma once

#include <QJsonObject>
#include <optional>

#include "config/deformation_model_config.h"
#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/deformation_experiment.h"
#include "core/sim/shaft/lathe_setup.h"
#include "devices/parsers/gcode_writer.h"

namespace tt::config {

/// A feed-scheduling preset (resources/presets/feed-scheduling.json): the simulated lathe the
/// experiments are cut on, the experiment grid, the machine job of the program and the planner's
/// default request.
struct FeedSchedulingSetup {
    core::LatheSetup lathe;
    core::DeformationExperimentPlan experiment;
    devices::FeedPassJob job;
    core::FeedScheduleRequest request;
};

/// Reads the sections of a feed-scheduling preset:
///   "lathe": as latheSetupFromJson,
///   "experiment": {"depths_mm": [..], "feeds_mm_per_rev": [..], "z_mm": {"from", "to", "step"}, "seed"},
///   "job": as feedPassJobFromJson, finish_diameter_mm defaulting to the lathe's finished diameter,
///   "schedule": {"depth_mm", "feed_min_mm_per_rev", "feed_max_mm_per_rev", "feed_step_mm_per_rev",
///                "z_start_mm", "z_end_mm", "level_fraction", "min_length_mm"}.
/// Throws std::invalid_argument naming the field ("experiment.z_mm.step: ...").
FeedSchedulingSetup feedSchedulingSetupFromPreset(const QJsonObject& preset);

/// The machine job of a preset ("job" section, the finished diameter defaulting to the lathe's), or
/// nothing when the preset has no "job". Throws std::invalid_argument naming a bad field.
std::optional<devices::FeedPassJob> feedPassJobFromPreset(const QJsonObject& preset);

/// The program content of a schedule: the segments and header notes naming the model (terms, R²,
/// residual 2σ, source), the level Yc with Y1 and Y2, the feed range and step, L_min and the times.
devices::FeedPassProgram feedPassProgram(const core::FeedSchedule& schedule, const core::FeedScheduleRequest& request,
                                         const DeformationModelFile& model);

}  // namespace tt::config
