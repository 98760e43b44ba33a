#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <optional>

#include "core/control/run_to_run_setup.h"
#include "core/model/disturbance_model.h"

namespace tt::config {

/// Reads a run-to-run scenario preset (resources/presets/paper-2012.json) into the engine's setup:
///
///   "plant": {
///     "part_length_mm": 325,                 the paper's five points on this length when no points are given
///     "points_mm": [0, 27.5, ...],           or "points": [{"x_mm", "gain", "disturbance",
///                                                           "gauge_noise_variance_mm2"}, ...] (1..16)
///     "gain": 2, "delay": 4,                 k_i and the default transport delay z (1..8)
///     "gauge_noise_variance_mm2": 2.5e-7,
///     "disturbance": [ component, ... ]      summed; a component is one of
///        {"type": "shaping_filter", "numerator": [..], "roots": [r | [re, im], ..] or "denominator": [..],
///         "variance_mm2": v or "input_variance_mm2": q}
///        {"type": "ar1", "pole": a, "variance_mm2": v}
///        {"type": "random_walk", "step_variance_mm2": q}
///        {"type": "white", "variance_mm2": v}
///   },
///   "controller": {
///     "output_weight": 1 | [per point],      R1 diagonal
///     "correction_weight": 0.01 | [..],      R2 diagonal
///     "max_correction_mm": 0.3, "max_step_mm": 0.1,
///     "gate_sigma": 5, "history_parts": 64,
///     "ewma": {"weight": "auto" | 0.3, "dead_band_mm": 0, "warning_mm": .., "alarm_mm": ..}
///   }
///
/// `delay` (the command line's --delay) overrides plant.delay. Throws std::invalid_argument naming the
/// field ("plant.disturbance[1].roots: ...") for anything missing, mistyped or out of range, and for
/// an unstable shaping filter (naming the root).
core::RunToRunSetup runToRunSetupFromPreset(const QJsonObject& preset, std::optional<int> delay = std::nullopt);

/// Loads the preset `nameOrPath` (PresetLibrary::load) and reads it with runToRunSetupFromPreset.
/// Errors name the preset: "preset 'paper-2012': plant.delay: ...".
core::RunToRunSetup loadRunToRunSetup(const QString& nameOrPath, std::optional<int> delay = std::nullopt);

/// The most components of one disturbance model (a preset with 1000 of them never finished).
inline constexpr int kMaxDisturbanceComponents = 8;
/// The highest order (states per control point) of one disturbance model.
inline constexpr int kMaxDisturbanceOrder = 12;

/// One disturbance model (an array of components, at most kMaxDisturbanceComponents of total order at
/// most kMaxDisturbanceOrder) at `where` (for messages).
core::DisturbanceModel disturbanceFromJson(const QJsonValue& value, const QString& where);

}  // namespace tt::config
