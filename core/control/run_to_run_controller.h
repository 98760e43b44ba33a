#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/notice.h"
#include "core/ports/controller_state.h"

namespace tt::core {

/// The gauged deviations of one finished part at the control points:
/// measured minus nominal diameter, mm. NaN at a point = that point was not measured.
struct PartMeasurement {
    std::int64_t partNumber = 0;
    Eigen::VectorXd deviationMm;
};

/// Verdict on one offered measurement, per control point.
struct MeasurementVerdict {
    std::vector<bool> accepted;   ///< per point: used by the controller
    std::vector<Notice> reasons;  ///< per point: why it was rejected (kind None when accepted)

    /// Every point of the measurement was used.
    bool allAccepted() const {
        for (bool a : accepted)
            if (!a) return false;
        return true;
    }
};

/// The innovation of one measurement under the controller's model: measured minus predicted deviation
/// and the variance the model predicts for it (paper 000's Kalman filter; white with that variance while
/// the plant matches the model). NaN at a point without a finite value.
struct Innovation {
    std::int64_t partNumber = 0;
    Eigen::VectorXd valueMm;      ///< per point, mm
    Eigen::VectorXd varianceMm2;  ///< per point, mm^2 (> 0)
    /// Correlation of the normalised innovations of the points at the same part as the model says (points x
    /// points); empty: independent (the preset's model). An identified model has it from its prediction errors.
    Eigen::MatrixXd correlation = {};
    /// The model's actuation lag: the correction sent for part k acts on part k + lagParts (0: on part k).
    int lagParts = 0;
};

/// A run-to-run (part-to-part) controller of the diameter profile at N control points
/// (paper 000, outer loop, one step per part). Parts are machined in increasing part number;
/// measurements of finished parts arrive later (transport delay z parts) and possibly out of order.
class RunToRunController {
public:
    virtual ~RunToRunController() = default;

    /// The controller's kind as stored with its state: "lqg", "ewma", "open".
    virtual std::string name() const = 0;
    /// Number of control points N (values per measurement and per correction).
    virtual int pointCount() const = 0;

    /// Offers the measurement of an already machined part. Outliers (NaN, Inf, far outside the
    /// predicted range) are rejected per point with a reason and leave the state untouched.
    virtual MeasurementVerdict addMeasurement(const PartMeasurement& measurement) = 0;

    /// Radial cutter corrections (mm, one per control point) for part `partNumber`, after the
    /// limits (absolute range, max change per part). The returned, clamped values are what the
    /// controller assumes was applied. Part numbers must increase by one per call.
    virtual Eigen::VectorXd nextCorrection(std::int64_t partNumber) = 0;

    /// The correction really sent for part `partNumber` (the last part asked for) differs from what
    /// nextCorrection returned: the loop's own limits, a hold, the fade of a controller transfer or a dither
    /// changed it. A controller with a model of its past corrections takes `appliedMm` as the applied one, so
    /// its estimate stays consistent with what the parts received. Ignored for any other part number.
    virtual void correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) {
        (void)partNumber;
        (void)appliedMm;
    }

    /// The complete state, so that a restored controller continues exactly (resume after a restart).
    virtual ControllerState saveState() const = 0;
    /// Restores a state saved by the same kind of controller with the same configuration;
    /// throws std::invalid_argument otherwise.
    virtual void restoreState(const ControllerState& state) = 0;

    /// The innovation of the last measurement offered at its own filter step (before it was gated), for
    /// the loop's mismatch monitor; none for a controller without a model of the plant (EWMA, open loop).
    virtual std::optional<Innovation> lastInnovation() const { return std::nullopt; }
};

}  // namespace tt::core
