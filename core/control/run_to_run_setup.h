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

/// The controllers a run can use.
enum class ControllerKind { Lqg, Ewma, Open };

/// "lqg", "ewma", "open".
std::string controllerKindName(ControllerKind kind);
/// Parses "lqg", "ewma", "open"; throws std::invalid_argument otherwise.
ControllerKind controllerKindFromName(const std::string& name);

/// Builds the controller of `kind` for a built plant (LQG: designLqg with the setup's weights; EWMA: the
/// setup's options with `ewmaWeight` as lambda).
std::unique_ptr<RunToRunController> makeRunToRunController(const RunToRunSetup& setup, const RunToRunPlant& plant,
                                                           ControllerKind kind, double ewmaWeight);

}  // namespace tt::core
