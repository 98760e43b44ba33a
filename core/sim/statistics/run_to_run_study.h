#pragma once

#include <optional>
#include <vector>

#include "core/control/run_to_run_setup.h"
#include "core/sim/statistics/run_to_run_monte_carlo.h"

namespace tt::core {

/// What to study: which controller, its EWMA weight (empty = best on the grid) and the Monte-Carlo run.
struct StudyOptions {
    ControllerKind controller = ControllerKind::Lqg;
    std::optional<double> ewmaWeight;  ///< lambda for ControllerKind::Ewma; empty = `auto`
    MonteCarloOptions monteCarlo;
};

/// One control point of a study: Monte-Carlo variances and k_eff, and the analytic k_eff.
struct StudyPoint {
    double xMm = 0.0;
    double varOpenMm2 = 0.0;
    double varClosedMm2 = 0.0;
    double kEff = 0.0;
    double kEffAnalytic = 0.0;  ///< NaN when the open loop is not stationary
};

/// Result of `trueturn simulate`: Monte-Carlo and analytic k_eff of one controller on one plant.
struct StudyResult {
    ControllerKind controller = ControllerKind::Lqg;
    int delay = 1;
    std::int64_t parts = 0;
    std::optional<double> ewmaWeight;  ///< the weight used (EWMA only)
    std::vector<StudyPoint> points;
    double kEff = 0.0;          ///< Monte-Carlo, sum open / sum closed
    double kEffAnalytic = 0.0;  ///< analytic, sum open / sum closed (NaN when not available)
    std::int64_t rejectedValues = 0;
};

/// Builds the plant of `setup`, the controller, runs the Monte-Carlo simulation and the analytic
/// steady-state analysis (paper 000, Table 2 per delay).
StudyResult runRunToRunStudy(const RunToRunSetup& setup, const StudyOptions& options);

}  // namespace tt::core
