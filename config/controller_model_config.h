#pragma once

#include <QJsonObject>
#include <optional>

#include "core/control/run_to_run_setup.h"
#include "core/ports/adaptation_record.h"

namespace tt::config {

/// The preset's "controller_model" section: the controller's own, identified model of the plant (`trueturn tune`
/// writes it; the next runs design their controllers on it while the simulator keeps the "plant" section):
///
///   "controller_model": {
///     "source": "run 7 of history.db, parts 101 .. 1100",   where it was identified (optional)
///     "lag_parts": 0,                                        the plant's extra delay: delay z + lag
///     "innovation_correlation": [[1, 0.8, ..], ..],          optional, points x points
///     "points": [{"gain": 1.93, "disturbance": [ component ]}, ..]   one per control point (components as in
///                                                                      "plant.disturbance")
///   }
///
/// The points may carry the identification's figures too (gain_std_error, ar, ma, ar_std_errors, ma_std_errors,
/// noise_variance_mm2, mean_mm); they are for people and not read. None when the preset has no such section.
/// Throws std::invalid_argument naming the field ("controller_model.points[2].gain: ...") when it does not fit a
/// plant of `points` control points and delay `delay`.
std::optional<core::ControllerModel> controllerModelFromPreset(const QJsonObject& preset, std::size_t points,
                                                               int delay);

/// An identified model (core::modelRecord) as that section, with its figures.
QJsonObject controllerModelJson(const core::PlantModelRecord& model);

}  // namespace tt::config
