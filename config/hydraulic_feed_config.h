#pragma once

#include <QJsonObject>
#include <QString>

#include "core/sim/hydraulic/feed_study.h"

namespace tt::config {

/// A hydraulic feed scenario preset (resources/presets/hydraulic-feed.json, paper 003):
///
///   "cylinder": {"mass_kg", "piston_diameter_m", "leakage_m3_per_s_pa", "set_feed_m_per_s"},
///   "slot": {"discharge_coefficient", "plunger_diameter_m", "pressure_drop_pa", "oil_density_kg_per_m3",
///            "max_opening_m"},
///   "spool": {"time_constant_s", "damping_ratio", "gain_m_per_n", "lap_m"},
///   "magnet": {"turns", "gap_permeance_h", "gap_area_m2", "resistance_ohm"},
///   "amplifier": {"bias_v", "gain"},
///   "sensor": {"gain_v_per_n", "feed_exponent"},
///   "load": [{"time_s", "force_n", "duration_s" (optional: a ramp)}, ...],
///   "simulation": {"duration_s", "sample_s", "start": "running" | "rest"}
///
/// Every field is optional (core::HydraulicFeedParams' defaults, the paper's set-up; no load; 0.4 s at
/// 0.5 ms from the running carriage). Throws std::invalid_argument naming the field and its limits
/// ("spool.damping_ratio: 20 is outside 0.05 .. 10").
core::FeedScenario hydraulicFeedScenarioFromPreset(const QJsonObject& preset);

/// Loads `nameOrPath` (PresetLibrary::load) and reads it; errors name the preset.
core::FeedScenario loadHydraulicFeedScenario(const QString& nameOrPath);

/// The parameters as the preset's sections (the inverse of the reading above).
QJsonObject hydraulicFeedParamsToJson(const core::HydraulicFeedParams& params);

}  // namespace tt::config
