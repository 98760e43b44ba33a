#pragma once

#include <QJsonObject>

#include "core/control/integral_action.h"
#include "core/loop/adaptation_config.h"
#include "core/loop/mismatch_monitor.h"
#include "core/sim/shaft/plant_mismatch.h"

namespace tt::config {

/// The preset's "plant_mismatch" section (the simulated plant only; absent: the plant matches the model):
///   "plant_mismatch": {"gain_factor": 1.0, "delay": z, "step": {"at_part": N, "size_mm": S, "point": I}}
/// with `point` 1-based (absent: the whole part). Throws std::invalid_argument naming the field.
core::PlantMismatch plantMismatchFromPreset(const QJsonObject& preset);

/// "controller": {"integral": {"enabled": false, "weight": 0.3}}: the LQG's integral action.
core::IntegralAction integralActionFromPreset(const QJsonObject& preset);

/// "loop": {"mismatch_monitor": {"enabled": true, "window_parts": 50, "min_parts": 10,
///          "false_alarm_probability": 1e-6, "action": "adapt" | "propose" | "hold" | "alarm"}}.
core::MismatchMonitorConfig mismatchMonitorFromPreset(const QJsonObject& preset);

/// "loop": {"adaptation": {"window_parts": 1000, "retry_parts": 25, "transfer_parts": 10, "dither_share": 0,
///          "max_extra_lag": 2, "max_arma_order": 2, "criterion": "bic" | "aic", "max_gain_std_error": 0.25,
///          "min_delay_evidence": 10, "min_parts": 150, "refine_below": 0.05, "refine_parts": 200}}
///          (core/loop/adaptation_config.h).
core::AdaptationConfig adaptationFromPreset(const QJsonObject& preset);

}  // namespace tt::config
