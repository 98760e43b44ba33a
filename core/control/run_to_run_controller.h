#pragma once

#include <cstdint>
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

    /// The complete state, so that a restored controller continues exactly (resume after a restart).
    virtual ControllerState saveState() const = 0;
    /// Restores a state saved by the same kind of controller with the same configuration;
    /// throws std::invalid_argument otherwise.
    virtual void restoreState(const ControllerState& state) = 0;
};

}  // namespace tt::core
