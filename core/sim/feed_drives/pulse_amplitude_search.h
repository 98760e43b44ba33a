#pragma once

#include "core/sim/feed_drives/corner_simulation.h"

namespace tt::core {

/// The best corrective pulse for one move and what it achieves.
struct PulseOptimum {
    double amplitudeV = 0.0;  ///< minimises U within ±limit, V
    CornerCost with;          ///< cost with that pulse
    CornerCost without;       ///< cost without a pulse
    int simulations = 0;      ///< corners simulated to find it
};

/// Settings of the amplitude search.
struct PulseSearchSettings {
    int gridPoints = 11;       ///< coarse grid over ±limit that brackets the minimum
    double toleranceV = 2e-4;  ///< Brent's abscissa tolerance, V
    int maxSimulations = 40;   ///< including the grid
};

/// Finds the amplitude that minimises U = k1 e_max + k2 e_mean for `move` on the simulator (paper
/// 002's training targets): the coarse grid brackets the minimum, Brent's method refines it
/// (minimiseOnGrid). Deterministic.
PulseOptimum findBestPulse(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const CornerMove& move,
                           const PulseSettings& pulse, const PulseSearchSettings& search = {});

}  // namespace tt::core
