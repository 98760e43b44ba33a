#pragma once

#include "core/common/notice.h"

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/loop/loop_config.h"

namespace tt::core {

/// What the limiter did to one part's corrections.
struct LimiterOutcome {
    std::vector<double> appliedMm;  ///< what may go to the CNC, radial mm
    std::vector<Notice> notes;      ///< one per point that was changed (CorrectionHeld, CorrectionLimited)
};

/// Keeps the corrections sent to the CNC inside the loop's limits: a value that is not a number holds
/// the last applied value; then applyCorrectionLimits (the step around the last applied value, then the
/// absolute range). Starts from zero.
class CorrectionLimiter {
public:
    /// `pointZMm`: the control points along the part (mm), named in the notes; nothing applied yet (zeros).
    CorrectionLimiter(CorrectionLimits limits, std::vector<double> pointZMm);

    /// Limits `computedMm` (one per point) against the last applied corrections and remembers the result.
    LimiterOutcome apply(const Eigen::VectorXd& computedMm);
    /// The last applied corrections (zeros before the first part).
    const std::vector<double>& lastAppliedMm() const { return m_last; }
    /// Sets the last applied corrections (on resume).
    void setLastApplied(std::vector<double> appliedMm);

private:
    CorrectionLimits m_limits;
    std::vector<double> m_pointZ;
    std::vector<double> m_last;
};

}  // namespace tt::core
