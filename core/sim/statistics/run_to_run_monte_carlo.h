#pragma once

#include <cstdint>
#include <vector>

#include "core/control/run_to_run_controller.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// Options of a Monte-Carlo run.
struct MonteCarloOptions {
    std::int64_t parts = 20000;      ///< parts counted in the statistics
    std::uint64_t seed = 1;          ///< random seed of the plant
    std::int64_t warmupParts = 100;  ///< parts machined first and not counted (controller start-up)
};

/// Sample variances of the true diameter deviation at one control point (mm^2).
struct MonteCarloPoint {
    double xMm = 0.0;
    double varOpenMm2 = 0.0;
    double varClosedMm2 = 0.0;
    double kEff = 0.0;  ///< varOpen / varClosed
};

/// Result of a Monte-Carlo run.
struct MonteCarloResult {
    std::vector<MonteCarloPoint> points;
    double kEff = 0.0;                ///< sum of open variances / sum of closed variances
    std::int64_t parts = 0;           ///< parts counted
    std::int64_t rejectedValues = 0;  ///< measured values the controller refused (gating, bands)
};

/// Monte-Carlo run-to-run simulation (paper 000, Fig. 7 and Table 2): parts 1, 2, ... are machined on
/// a StochasticPlant with the controller's corrections; the measurement of part p reaches the
/// controller just before the correction of part p + z is computed (transport delay z). The open loop
/// is the same disturbance realisation without correction. Statistics skip the warm-up parts.
/// Throws std::invalid_argument when the controller's point count differs from the plant's or
/// parts < 2.
MonteCarloResult runMonteCarlo(const RunToRunPlant& plant, RunToRunController& controller,
                               const MonteCarloOptions& options);

}  // namespace tt::core
