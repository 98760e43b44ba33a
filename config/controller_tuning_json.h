#pragma once

#include <QJsonObject>

#include "core/control/run_to_run_setup.h"

namespace tt::config {

/// The controller tuning the Controller page applies (what core::withControllerTuning takes from a setup), as
/// JSON, so a run request can carry it and the history store it with the run:
///
///   {"output_weight": [[R1]], "correction_weight": [[R2]],      full matrices, one row per control point
///    "max_correction_mm": 0.3, "max_step_mm": 0.1,              left out when unlimited
///    "gate_sigma": 5, "history_parts": 64,
///    "ewma": {"weight", "dead_band_mm", "warning_mm", "alarm_mm", "drift_weight"}, "ewma_weight_auto": true,
///    "integral": {"enabled": false, "weight": 0.3},
///    "disturbances": [[component, ...] per control point]}      the preset's component format
///
/// Shaping filters are written by their coefficients and driving-noise variance, so reading gives the same
/// filter back.
QJsonObject controllerTuningToJson(const core::RunToRunSetup& setup);

/// `base` with the tuning of `json` (controllerTuningToJson's format) in place of its own: weights, limits,
/// LQG and EWMA options, integral action and each point's disturbance model; the plant's points, gains and
/// delay stay `base`'s. Throws std::invalid_argument naming the field ("tuning.disturbances[2]: ...") for
/// anything missing, mistyped, out of range or with another number of control points than `base`.
core::RunToRunSetup tunedSetupFromJson(const QJsonObject& json, core::RunToRunSetup base);

}  // namespace tt::config
