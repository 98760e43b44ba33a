#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/control/lqg_design.h"
#include "core/control/run_to_run_plant.h"
#include "core/control/run_to_run_setup.h"

namespace tt::core {

/// A linear run-to-run controller in state-space form, step k = measurement of part k:
/// `xi(k+1) = Ac xi(k) + Bc y(k)`, `u(k) = Cc xi(k) + Dc y(k)` (u(k) is the correction of part k + z).
/// Limits, dead bands and gating are not part of it (they are inactive in steady state when the
/// limits are wide).
struct LinearControllerModel {
    Eigen::MatrixXd Ac, Bc, Cc, Dc;
};

/// The LQG controller (current estimator, u = -K x(k|k)) in that form: xi = x(k|k-1),
/// Ac = (A - BK)(I - LC), Bc = (A - BK)L, Cc = -K(I - LC), Dc = -KL.
LinearControllerModel lqgControllerModel(const RunToRunPlant& plant, const LqgDesign& design);

/// The EWMA controller with weight lambda at every point: xi = [offset; u(k-1) .. u(k-z)],
/// offset(k) = (1 - lambda) offset(k-1) + lambda (y(k) - k_i u(k-z)), u(k) = -offset(k) / k_i.
LinearControllerModel ewmaControllerModel(const RunToRunPlant& plant, double weight);

/// Open loop: u = 0.
LinearControllerModel openLoopControllerModel(const RunToRunPlant& plant);

/// Steady-state variances of the true diameter deviation (without gauge noise) per control point.
struct SteadyStateVariances {
    bool available = false;     ///< false when the open loop is not stationary (random walk)
    Eigen::VectorXd openMm2;    ///< open loop (u = 0)
    Eigen::VectorXd closedMm2;  ///< closed loop (+infinity when the loop is unstable)
    Eigen::VectorXd kEff;       ///< open / closed per point (paper 000: k_eff = sigma_p^2 / sigma_z^2)
    double kEffOverall = 0.0;   ///< sum of open variances / sum of closed variances
};

/// Analytic steady state from the closed-loop Lyapunov equation Sigma = Phi Sigma Phi' + Gamma Xi Gamma'
/// of the plant driven by w and v with the controller in the loop (paper 000's k_eff without simulation).
SteadyStateVariances analyseSteadyState(const RunToRunPlant& plant, const LinearControllerModel& controller);

/// The EWMA weight with the smallest summed closed-loop variance on `grid` and that variance.
struct EwmaWeightChoice {
    double weight = 0.0;
    double closedVarianceSumMm2 = 0.0;
};

/// The weights 0.05, 0.10, ..., 1.00.
std::vector<double> defaultEwmaWeightGrid();

/// Best EWMA weight on `grid` by the analytic steady state (`--ewma-weight auto`). Throws
/// std::invalid_argument when the open loop is not stationary (no analytic variance exists).
EwmaWeightChoice bestEwmaWeight(const RunToRunPlant& plant, const std::vector<double>& grid);

/// The EWMA weight a run uses: `given`, else the best on the default grid when the setup says auto, else
/// the setup's own. Throws as bestEwmaWeight.
double chooseEwmaWeight(const RunToRunSetup& setup, const RunToRunPlant& plant, std::optional<double> given);

/// The linear model of the controller of `kind` (LQG designed with the setup's weights; EWMA with
/// `ewmaWeight`; open loop) for the analytic steady state.
LinearControllerModel controllerModel(const RunToRunSetup& setup, const RunToRunPlant& plant, ControllerKind kind,
                                      double ewmaWeight);

}  // namespace tt::core
