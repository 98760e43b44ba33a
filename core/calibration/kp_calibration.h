#pragma once

#include <string>
#include <vector>

namespace tt::core {

/// One known load on the cross slide and the current difference it produced: a load of known
/// size (dynamometer, hydraulic jack with a gauge) pushes the tool towards the axis like the
/// cutting force, the cross feed dithers, and ΔI = (I_fwd − I_rev) / 2 is read at constant
/// velocity (DitherForceEstimator with k_p = 1 gives it as its force).
struct KpPoint {
    double loadN = 0.0;               ///< known radial load, N (towards the axis: positive)
    double currentDifferenceA = 0.0;  ///< (I_fwd − I_rev) / 2, A
};

/// The current-to-force gain from known loads (paper 001: k_p "found experimentally";
/// P = k_p (I_fwd − I_rev) / 2): least squares P = k_p ΔI + offset.
struct KpFit {
    double kpNPerA = 0.0;
    double offsetN = 0.0;  ///< force at ΔI = 0 (drive asymmetry); ideally near 0
    double r2 = 0.0;
    std::vector<double> residualsN;  ///< load − fitted, per point
    double rmsResidualN = 0.0;
};

/// Fits k_p; throws std::invalid_argument when there are fewer than 3 points, fewer than 2
/// different loads, a non-finite value, or when ΔI does not grow with the load (k_p ≤ 0: the
/// load acts the other way or the current sign is reversed).
KpFit fitKp(const std::vector<KpPoint>& points);

}  // namespace tt::core
