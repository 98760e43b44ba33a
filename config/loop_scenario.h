#pragma once

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>

#include "core/control/profile_interpolation.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_config.h"
#include "core/model/scaled_polynomial.h"
#include "core/sim/shaft/lathe_setup.h"
#include "core/sim/shaft/lathe_shop.h"
#include "core/sim/shaft/lathe_station.h"

namespace tt::config {

/// Everything a closed-loop run on the built-in simulator takes from a preset: the controller's plant
/// and weights ("plant", "controller": config/plant_config.h), the physical lathe ("lathe", optional:
/// without it the statistical plant is the machine), the systematic model for the feed-forward
/// ("systematic_model", optional) and the loop's own settings:
///
///   "based_on": "paper-2012",          sections this preset does not have come from that preset
///   "loop": {"nominal_diameter_mm", "part_length_mm", "plausible_range_mm": 0.5, "path_step_mm": 0.5,
///            "interpolation": "pchip" | "spline", "gauge_timeout_s": 600, "tolerance_mm": 0.03}
struct LoopScenario {
    QString preset;    ///< name or path it was loaded from
    QJsonObject json;  ///< the preset with the sections of its base merged in
    core::RunToRunSetup control;
    std::optional<core::LatheSetup> lathe;
    core::LatheStationTiming timing;
    std::optional<core::ScaledPolynomial> systematicModel;
    double nominalDiameterMm = 27.0;
    double partLengthMm = 325.0;
    double plausibleRangeMm = 0.5;
    double pathStepMm = 0.5;
    double gaugeTimeoutS = 600.0;
    double toleranceMm = 0.03;  ///< ± band on diameter shown with the profile (loop.tolerance_mm)
    core::InterpolationMethod interpolation = core::InterpolationMethod::Pchip;

    /// The transport delay z of the plant (after any override).
    int delay() const { return control.plant.delay; }
    /// The simulated shop with every random source seeded by `seed`.
    core::LatheShopSpec shopSpec(std::uint64_t seed) const;
    /// The loop settings; the feed-forward only when `feedForward` and the preset has a model.
    core::LoopConfig loopConfig(bool feedForward, std::optional<std::int64_t> lastPartNumber) const;
};

/// Loads `nameOrPath` (PresetLibrary::load, then "based_on") and reads it; `delay` overrides the
/// plant's. Throws std::invalid_argument naming the preset and the field.
LoopScenario loadLoopScenario(const QString& nameOrPath, std::optional<int> delay = std::nullopt);

}  // namespace tt::config
