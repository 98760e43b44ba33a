#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/control/margins.h"
#include "core/control/run_to_run_setup.h"

namespace tt::core {

/// What a commissioning engineer sees while tuning the run-to-run controller (issue 13 item 6), all
/// analytic (no simulation): the LQG design of the setup beside the best EWMA and the open loop on the
/// same plant.
struct TuningPreview {
    bool varianceAvailable = false;  ///< false with a random-walk disturbance (no stationary variance)
    Eigen::VectorXd openMm2;         ///< open-loop variance per point, mm^2
    Eigen::VectorXd lqgMm2;          ///< LQG closed-loop variance per point, mm^2
    Eigen::VectorXd lqgKEff;         ///< open / LQG per point (paper 000's k_eff)
    Eigen::VectorXd ewmaKEff;        ///< open / EWMA per point
    double ewmaWeight = 0.0;         ///< the EWMA weight compared (best on the default grid)
    LoopMargins lqgMargins;          ///< robustness of the LQG design, per point
    LoopMargins ewmaMargins;         ///< and of the EWMA
    /// Response of point 0's diameter error to a unit step disturbance at part 0 (a tool change), parts
    /// 0 .. kPreviewSteps - 1: LQG, EWMA and open loop (the step itself).
    std::vector<double> stepLqg, stepEwma, stepOpen;
    /// |S(e^jw)| of point 0 at `frequencyRadPerPart`: LQG and EWMA.
    std::vector<double> frequencyRadPerPart, sensitivityLqg, sensitivityEwma;
};

/// Parts of the step response shown.
inline constexpr int kPreviewSteps = 40;
/// Frequencies of the sensitivity plot (uniform on (0, pi]).
inline constexpr int kPreviewFrequencies = 96;

/// Designs the LQG controller of `setup` (with integral action when setup.integral is on: designed on
/// withIntegralAction's plant, its variances analysed on the true plant) and computes the preview. The EWMA and
/// open-loop figures depend on the plant only: `samePlant`, a preview of a setup with the same plant (samePlantSpec),
/// lends them so a weight change costs the LQG part alone. Throws std::invalid_argument for an invalid setup (the plant
/// builder's and the weights' messages).
TuningPreview computeTuningPreview(const RunToRunSetup& setup, const TuningPreview* samePlant = nullptr);

/// True when the two plant specifications are the same (points, gains, disturbances, gauge noise, delay).
bool samePlantSpec(const RunToRunPlantSpec& a, const RunToRunPlantSpec& b);

/// The response of point `point`'s error to a unit step disturbance at part 0 through the loop of
/// `controller` (u(k) the correction of part k + z), parts 0 .. steps - 1; no noise.
std::vector<double> stepResponse(const RunToRunPlant& plant, const Eigen::MatrixXd& Ac, const Eigen::MatrixXd& Bc,
                                 const Eigen::MatrixXd& Cc, const Eigen::MatrixXd& Dc, int point, int steps);

}  // namespace tt::core
