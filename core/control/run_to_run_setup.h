#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/control/correction_limits.h"
#include "core/control/ewma_controller.h"
#include "core/control/integral_action.h"
#include "core/control/lqg_controller.h"
#include "core/control/lqg_design.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// Everything a run-to-run scenario fixes (a preset such as `paper-2012`): the plant, the LQG weights,
/// the correction limits and the controllers' options.
struct RunToRunSetup {
    RunToRunPlantSpec plant;
    LqgWeights weights;
    CorrectionLimits limits;
    LqgControllerOptions lqg;
    EwmaOptions ewma;
    bool ewmaWeightAuto = true;  ///< choose the EWMA weight on a grid (fair baseline) unless one is given
    IntegralAction integral;     ///< LQG only: the integrating disturbance state of the design model
};

/// lambda2 of the double EWMA when the setup gives none (Butler & Stefani 1994 use 0.05 .. 0.2).
inline constexpr double kDefaultDriftWeight = 0.1;

/// The controllers a run can use (Dewma: double EWMA, the peer for drifts and steps).
enum class ControllerKind { Lqg, Ewma, Open, Dewma };

/// "lqg", "ewma", "open", "dewma".
std::string controllerKindName(ControllerKind kind);
/// Parses "lqg", "ewma", "open", "dewma"; throws std::invalid_argument otherwise.
ControllerKind controllerKindFromName(const std::string& name);

/// Builds the controller of `kind` for a built plant (LQG: designLqg with the setup's weights; EWMA: the
/// setup's options with `ewmaWeight` as lambda; double EWMA: the same with the setup's drift weight and the
/// plant's delay as the drift horizon).
std::unique_ptr<RunToRunController> makeRunToRunController(const RunToRunSetup& setup, const RunToRunPlant& plant,
                                                           ControllerKind kind, double ewmaWeight);

}  // namespace tt::core
