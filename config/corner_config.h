#pragma once

#include <QJsonObject>
#include <QString>

#include "core/sim/feed_drives/corner_scenario.h"

namespace tt::config {

/// Reads a corrective-pulse preset (resources/presets/1v340-feed-drives.json, paper 002):
///
///   "drives": {"step_ms", "x": {AXIS}, "z": {AXIS}} with AXIS = {"inertia_kg_m2",
///             "torque_constant_nm_per_a", "current_limit_a", "viscous_friction_nm_s_per_rad",
///             "coulomb_friction_nm", "static_friction_nm", "stribeck_speed_rad_per_s", "screw_lead_mm",
///             "encoder_step_mm", "position_gain_per_s", "speed_per_volt_rad_per_s_per_v", "command_limit_v",
///             "velocity_gain_a_per_rad_per_s", "velocity_integral_time_s"},
///   "cost": {"t1_s", "t2_s", "k1", "k2"},
///   "pulse": {"axis": "x"|"z", "lead_s", "duration_s", "limit_v"},
///   "speeds": {"x_rad_per_s": [min, max], "z_rad_per_s": [min, max]},
///   "training": {"moves", "seed", "grid_points", "tolerance_v", "max_simulations", "hidden", "max_epochs",
///                "patience", "validation_fraction", "learning_rate", "network_seed"},
///   "retraining": {"window_corners", "threshold_pct", "outlier_mads", "old_set_weight",
///                  "friction_factor_min", "friction_factor_max", "inertia_factor_min", "inertia_factor_max",
///                  "gain_factor_min", "gain_factor_max", "identification_sweeps", "validation_moves"},
///   "machine": {"friction_scatter", "outlier_probability", "outlier_torque_nm", "outlier_duration_s", "seed"},
///   "work": {"moves"}
///
/// Every field is optional (the engine's defaults, which are the 1v340-feed-drives values). Throws
/// std::invalid_argument naming the field ("drives.z.screw_lead_mm: 0 is outside 0.1 .. 100").
core::CornerScenario cornerScenarioFromPreset(const QJsonObject& preset);

/// Loads `nameOrPath` (PresetLibrary::load) and reads it; errors name the preset.
core::CornerScenario loadCornerScenario(const QString& nameOrPath);

/// The built-in corrective-pulse preset.
inline const QString kDefaultCornerPreset = QStringLiteral("1v340-feed-drives");
/// The same lathe with soft drives, where the inertia moves the best pulse (docs/DECISIONS.md, "Drift kinds").
inline const QString kSoftDrivesCornerPreset = QStringLiteral("1v340-soft-drives");

}  // namespace tt::config
