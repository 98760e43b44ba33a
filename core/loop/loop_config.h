#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "core/control/profile_interpolation.h"
#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// Safety limits of the radial corrections the loop sends to the CNC, mm. The controller has its
/// own limits; these are the loop's last line: whatever the controller returns, what reaches the CNC
/// stays inside them.
struct CorrectionLimits {
    double maxAbsMm = 0.5;   ///< |u_i| <= maxAbs
    double maxStepMm = 0.1;  ///< |u_i(k) - u_i(k-1)| <= maxStep
};

/// How the closed loop runs (paper 000's outer loop).
struct LoopConfig {
    std::vector<double> pointZMm;    ///< control points along the part, mm, strictly increasing
    double partLengthMm = 0.0;       ///< > 0
    double nominalDiameterMm = 0.0;  ///< > 0
    int delayParts = 1;              ///< z: the measurement of part k is used for part k + z (1 .. 8)
    /// Systematic diameter error d(x) (Table 1 type model); when set, the path carries the
    /// feed-forward y_ff = -d/2.
    std::optional<ScaledPolynomial> systematicModel;
    InterpolationMethod interpolation = InterpolationMethod::Pchip;
    double pathStepMm = 0.5;        ///< sampling of the path sent to the CNC, mm
    double plausibleRangeMm = 0.5;  ///< a reading farther than this from the nominal is rejected, mm
    CorrectionLimits limits;
    double gaugeTimeoutS = 600.0;  ///< diameters due but not complete for this long: pause, s
    std::int64_t firstPartNumber = 1;
    /// The run ends after this part is machined and every part is measured; none = until stopped.
    std::optional<std::int64_t> lastPartNumber;
};

/// Throws std::invalid_argument naming the first bad value.
void validateLoopConfig(const LoopConfig& config);

}  // namespace tt::core
