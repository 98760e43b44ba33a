#pragma once

#include "core/calibration/current_difference_meter.h"
#include "core/control/dither_force_estimator.h"

namespace tt::core {

/// The k_p calibration's current-difference meter over the dither force estimator (paper 001,
/// way 1): the estimator with k_p = 1 N/A and k_st = 1 N/mm gives ΔI = (I_fwd − I_rev) / 2, in A,
/// as its force, one estimate per stroke pair; its refusals become StrokeProblem kinds.
class DitherCurrentDifference final : public CurrentDifferenceMeter {
public:
    /// `tuning`: the estimator's thresholds (its k_p and k_st are replaced by 1).
    explicit DitherCurrentDifference(DitherEstimatorConfig tuning = {});

    void reset() override { m_estimator.reset(); }
    StrokePairReading update(const DriveSample& sample) override;

private:
    static DitherEstimatorConfig unit(DitherEstimatorConfig tuning);

    DitherForceEstimator m_estimator;
};

}  // namespace tt::core
