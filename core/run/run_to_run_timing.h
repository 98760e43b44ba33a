#pragma once

#include "core/control/run_to_run_setup.h"

namespace tt::core {

/// Measured speed of the run-to-run hot paths (`trueturn bench`), on one core.
struct RunToRunTimings {
    int points = 0;
    int delay = 0;
    long long states = 0;
    double lqgSynthesisUs = 0.0;       ///< designLqg on the built plant (median of repetitions)
    double controllerUpdateUs = 0.0;   ///< one part: addMeasurement + nextCorrection of the LQG controller
    double simPartStepsPerS = 0.0;     ///< StochasticPlant parts per second (all points of a part)
    double monteCarloPartsPerS = 0.0;  ///< closed-loop Monte-Carlo parts per second (plant + LQG + statistics)
};

/// Times the hot paths for `setup` (the paper plant at z = 4 in `trueturn bench`), spending roughly
/// `secondsPerPath` on each. Medians of batches, so a brief interruption does not skew the figure.
RunToRunTimings measureRunToRunHotPaths(const RunToRunSetup& setup, double secondsPerPath = 0.25);

}  // namespace tt::core
