#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/control/profile_interpolation.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_config.h"
#include "core/model/scaled_polynomial.h"
#include "core/sim/shaft/lathe_setup.h"
#include "core/sim/shaft/lathe_shop.h"
#include "core/sim/shaft/lathe_station.h"

namespace tt::core {

/// Everything a shaft run-to-run run takes from its scenario (a preset, or the settings stored with a
/// run), Qt-free: the controller's plant and weights, the physical lathe of the built-in simulator
/// (none: the statistical plant is the machine), the systematic model for the feed-forward and the
/// loop's own settings. config/loop_scenario.h reads it from JSON.
struct ShaftScenario {
    RunToRunSetup control;
    std::optional<LatheSetup> lathe;
    LatheStationTiming timing;
    std::optional<ScaledPolynomial> systematicModel;
    double nominalDiameterMm = 27.0;
    double partLengthMm = 325.0;
    double plausibleRangeMm = 0.5;
    double pathStepMm = 0.5;
    double gaugeTimeoutS = 600.0;
    double toleranceMm = 0.03;  ///< ± band on diameter shown with the profile
    /// The tolerance zone per control point for the verdicts (empty: nominal ± toleranceMm at every point).
    std::vector<ToleranceZone> tolerances;
    bool pauseOnScrap = false;  ///< the loop pauses on a scrap part
    InterpolationMethod interpolation = InterpolationMethod::Pchip;
    /// How the simulated plant differs from the controller's model (the simulated shop only).
    PlantMismatch plantMismatch;
    /// The loop's test of the controller's model and what it does on a mismatch.
    MismatchMonitorConfig mismatchMonitor;
    /// How the loop adapts on a mismatch (action adapt or propose).
    AdaptationConfig adaptation;

    /// The transport delay z of the plant (after any override).
    int delay() const { return control.plant.delay; }
    /// The simulated shop with every random source seeded by `seed`.
    LatheShopSpec shopSpec(std::uint64_t seed) const;
    /// The loop settings; the feed-forward only when `feedForward` and the scenario has a model.
    /// Throws std::invalid_argument (validateLoopConfig) on a bad value.
    LoopConfig loopConfig(bool feedForward, std::optional<std::int64_t> lastPartNumber) const;
    /// The tolerance zone of each control point (`tolerances`, or nominal ± toleranceMm).
    std::vector<ToleranceZone> pointTolerances() const;
};

}  // namespace tt::core
