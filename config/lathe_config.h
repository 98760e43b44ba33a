#pragma once

#include <QJsonObject>

#include "core/sim/shaft/lathe_setup.h"
#include "core/sim/shaft/lathe_station.h"

namespace tt::config {

/// Reads the "lathe" section of a preset: the physical simulator of a shaft turned between centres
/// (resources/presets/paper-2012-group*.json):
///
///   "lathe": {
///     "workpiece": {"length_mm", "finish_diameter_mm", "young_modulus_n_per_mm2"},
///     "cutting":   {"depth_mm", "feed_mm_per_rev", "speed_m_per_min", "feed_towards_headstock": true},
///     "force":     {"specific_force_n_per_mm2", "exponent", "lead_angle_deg",
///                   "reference_speed_m_per_min", "speed_exponent"},
///     "stiffness": {"headstock_n_per_mm", "tailstock_n_per_mm", "tool_n_per_mm"},
///     "warm_up":   {"diameter_shift_mm", "duration_parts"},
///     "tool_wear": {"diameter_growth_mm", "tool_life_parts", "change_repeatability_mm"},
///     "micrometer": {"resolution_mm", "error95_mm"},
///     "tool_setting_offset_mm", "element_length_mm", "random_common_share", "random_scale",
///     "station":   {"part_time_s", "measure_start_s", "per_point_s"}
///   }
///
/// Every field has the LatheSetup default when absent. Throws std::invalid_argument naming the field
/// ("lathe.stiffness.headstock_n_per_mm: ...") for a wrong type or a non-physical value.
core::LatheSetup latheSetupFromJson(const QJsonObject& lathe);

/// The "station" part of the "lathe" section (simulated shop-floor times).
core::LatheStationTiming stationTimingFromJson(const QJsonObject& lathe);

}  // namespace tt::config
