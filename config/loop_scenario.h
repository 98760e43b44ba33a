#pragma once

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>

#include "core/run/shaft_scenario.h"

namespace tt::config {

/// A shaft scenario (core::ShaftScenario) as a preset gives it: the controller's plant
/// and weights ("plant", "controller": config/plant_config.h), the physical lathe ("lathe", optional:
/// without it the statistical plant is the machine), the systematic model for the feed-forward
/// ("systematic_model", optional) and the loop's own settings:
///
///   "based_on": "paper-2012",          merged under this preset (config/preset_merge.h): objects key by key at
///                                      every depth, an array or a value replaces the base's, null removes
///   "loop": {"nominal_diameter_mm", "part_length_mm", "plausible_range_mm": 0.5, "path_step_mm": 0.5,
///            "interpolation": "pchip" | "spline", "gauge_timeout_s": 600, "tolerance_mm": 0.03,
///            "tolerance": {"fit": "h9"} | {"upper_mm": 0.0, "lower_mm": -0.052} | [one per control point],
///            "pause_on_scrap": false}
///   "tolerance" entries may name their own "nominal_mm" (default: the loop's); without "tolerance" the
///   verdicts use nominal ± tolerance_mm at every point.
///   "loop": {"mismatch_monitor": {...}, "adaptation": {...}}, "controller": {"integral": {...}} and
///   "plant_mismatch" (the simulated plant only): config/robust_config.h; "controller_model" (the controller's
///   identified model, `trueturn tune`): config/controller_model_config.h.
struct LoopScenario : core::ShaftScenario {
    QString preset;    ///< name or path it was loaded from
    QJsonObject json;  ///< the preset merged over its based_on chain: what runs (`simulate --dump-preset`)
};

/// The most based_on links from a preset to the end of its chain; a longer chain, or one that comes
/// back to a preset it passed, is refused with the chain in the message.
inline constexpr int kMaxBasedOnDepth = 8;

/// Loads `nameOrPath` (PresetLibrary::load, then "based_on") and reads it; `delay` overrides the
/// plant's. Throws std::invalid_argument naming the preset and the field.
LoopScenario loadLoopScenario(const QString& nameOrPath, std::optional<int> delay = std::nullopt);

}  // namespace tt::config
