#pragma once

#include <QJsonObject>
#include <QString>

#include "core/run/boring_run.h"

namespace tt::config {

/// Reads a boring scenario preset (resources/presets/heavy-boring.json, paper 001):
///
///   "tool": {"id", "name", "section": "round"|"rectangular", "diameter_mm" | "width_mm" + "height_mm",
///            "overhang_mm", "material", "youngs_modulus_mpa", "current_to_force_n_per_a",
///            "measured_stiffness_n_per_mm" (optional, with "measured_on", "measured_by")},
///   "bar": {"true_stiffness_factor"},
///   "cut": {"bore_length_mm", "feed_mm_per_rev", "spindle_rpm", "radial_specific_force_n_per_mm2",
///           "tangential_to_radial_ratio", "depth_start_mm", "depth_end_mm", "hardness_variation",
///           "hardness_wavelength_mm", "wear_force_increase", "approach_mm", "entry_ramp_mm",
///           "gauge_margin_mm"},
///   "drive": {"slide_mass_kg", "motor_inertia_kg", "coulomb_friction_n", "static_friction_n",
///             "viscous_friction_n_s_per_mm", "transmission_stiffness_n_per_mm",
///             "transmission_damping_n_s_per_mm", "current_to_force_n_per_a", "current_noise_a",
///             "velocity_noise_mm_per_s", "position_noise_mm"},
///   "dither": {"amplitude_mm", "period_s", "constant_velocity_fraction"},
///   "estimator": {"moving_velocity_mm_per_s", "plateau_tolerance", "min_plateau_samples",
///                 "min_stroke_mm", "max_speed_asymmetry", "max_stroke_s", "max_quiet_s",
///                 "max_pair_age_s", "strokes_averaged"},
///   "probe": {"adc_bits", "full_scale_gap_mm", "bridge_coefficients": [c0, c1, ..], "noise_rms",
///             "supply_variation", "supply_variation_period_s", "filter_time_constant_s", "cross_talk",
///             "sensor_position_fraction", "sample_rate_hz"},
///   "calibration": {"points", "readings_per_point", "span_fraction", "reference_resolution_um",
///                   "reference_noise_um", "degree": 2|3|4|"auto"},
///   "compensation": {"max_offset_mm", "max_rate_mm_per_s", "plc_cycle_ms"},
///   "simulation": {"step_ms", "seed"}
///
/// Every section and field except "tool" is optional (the engine's defaults). Throws
/// std::invalid_argument naming the field ("cut.feed_mm_per_rev: 5 is outside 0.01 .. 2").
core::BoringScenario boringScenarioFromPreset(const QJsonObject& preset);

/// Loads `nameOrPath` (PresetLibrary::load) and reads it; errors name the preset.
core::BoringScenario loadBoringScenario(const QString& nameOrPath);

}  // namespace tt::config
