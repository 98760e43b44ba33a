#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/control/correction_limits.h"
#include "core/control/ewma_controller.h"
#include "core/control/integral_action.h"
#include "core/control/lqg_controller.h"
#include "core/control/lqg_design.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// The controller's own model of the plant where it differs from the scenario's plant: identified from a run
/// (core/control/plant_identification.h, `trueturn tune`, the loop's adaptation, the Controller page's "Identify
/// from history"). The plant spec stays what the simulator uses; only the controller's design changes.
struct ControllerModel {
    std::vector<double> gain;                   ///< k_i per point (diameter per radial move)
    std::vector<DisturbanceModel> disturbance;  ///< per point
    /// The plant's extra delay: a correction sent for part k acts on part k + lagParts (plant delay z + lag).
    int lagParts = 0;
    /// Correlation of the points' one-step prediction errors at the same part (empty: independent); the
    /// mismatch monitor whitens the innovations with it.
    Eigen::MatrixXd innovationCorrelation;
    std::string source;  ///< where it comes from, for the record ("run 12, parts 101 .. 1100")

    /// Throws std::invalid_argument unless there is one gain (in (0, 100]) and one disturbance per point, the lag
    /// keeps z + lag within kMaxDelay and the correlation is empty or points x points.
    void validate(std::size_t points, int delay) const;
};

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
    /// The controller's identified model of the plant; none: `plant` is the model.
    std::optional<ControllerModel> model;
};

/// The plant the controllers are designed on: `plant`, or with the identified model's gains, disturbances and
/// the delay z + lag. Throws std::invalid_argument when the model does not fit the plant (ControllerModel::validate).
RunToRunPlantSpec designPlantSpec(const RunToRunSetup& setup);
/// The identified model's actuation lag (0 without a model).
int actuationLag(const RunToRunSetup& setup);

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
/// plant's delay as the drift horizon). With an identified model (setup.model) the plant is the design plant
/// (designPlantSpec, delay z + lag) and the controller is wrapped in a LaggedController with the model's lag and
/// innovation correlation.
std::unique_ptr<RunToRunController> makeRunToRunController(const RunToRunSetup& setup, const RunToRunPlant& plant,
                                                           ControllerKind kind, double ewmaWeight);

}  // namespace tt::core
