#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "core/common/tolerance.h"
#include "core/control/correction_limits.h"
#include "core/control/profile_interpolation.h"
#include "core/loop/adaptation_config.h"
#include "core/loop/mismatch_monitor.h"
#include "core/model/scaled_polynomial.h"

namespace tt::core {

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
    /// The loop's own limits on what reaches the CNC (the controller has its own; these are the last
    /// line: whatever the controller returns, the CNC gets values inside them).
    CorrectionLimits limits{0.5, 0.1};
    double gaugeTimeoutS = 600.0;  ///< diameters due but not complete for this long: pause, s
    std::int64_t firstPartNumber = 1;
    /// The run ends after this part is machined and every part is measured; none = until stopped.
    std::optional<std::int64_t> lastPartNumber;
    /// The tolerance zone of each control point (empty: no verdicts); every plausible reading gets a
    /// verdict and an out-of-tolerance one raises an "out-of-tolerance" alarm.
    std::vector<ToleranceZone> tolerances;
    bool pauseOnScrap = false;  ///< a scrap part pauses the loop (the operator continues it)
    /// The innovation test of the controller's model (a controller that reports innovations: LQG) and
    /// what the loop does when it fails.
    MismatchMonitorConfig mismatch;
    /// What the loop does on a mismatch with the action adapt or propose.
    AdaptationConfig adaptation;
};

/// Throws std::invalid_argument naming the first bad value.
void validateLoopConfig(const LoopConfig& config);

}  // namespace tt::core
