#pragma once

#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// Integral action of the LQG run-to-run controller: an integrating (random-walk) disturbance state added
/// to the controller's model of every control point, so that a step (a tool change, a new blank batch)
/// is estimated as a lasting offset and corrected completely. The simulated plant is not changed: the
/// state exists in the controller's model only.
struct IntegralAction {
    bool enabled = false;
    /// Step variance of the integrating state as a share of the point's stationary disturbance variance
    /// (dimensionless, 1e-6 .. 1): larger rejects a step faster and costs more k_eff on random disturbance.
    double weight = 0.3;

    /// Throws std::invalid_argument unless the weight is in 1e-6 .. 1.
    void validate() const;
};

/// Smallest and largest integral weight.
inline constexpr double kMinIntegralWeight = 1e-6;
inline constexpr double kMaxIntegralWeight = 1.0;

/// The controller's design plant with integral action: each point's disturbance model gains a random walk
/// whose step variance is weight x the point's stationary disturbance variance (the spec unchanged when
/// disabled). Throws std::invalid_argument for a bad weight or a point whose disturbance already has no
/// stationary variance (a random walk is already integral action).
RunToRunPlantSpec withIntegralAction(const RunToRunPlantSpec& spec, const IntegralAction& integral);

}  // namespace tt::core
