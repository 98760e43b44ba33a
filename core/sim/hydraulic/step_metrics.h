#pragma once

#include <vector>

namespace tt::core {

/// How a signal answered a disturbance (a load step): where it ended, how far it swung, how long it took.
struct StepMetrics {
    double finalValue = 0.0;     ///< the last value, the steady state the signal settled at
    double peakDeviation = 0.0;  ///< the largest |value - final| after the event, with its sign
    double peakTimeS = 0.0;      ///< when that deviation happened, s after the event
    double settlingS = 0.0;      ///< from the event until the signal stays within the band, s
    double overshootPct = 0.0;   ///< the largest swing past the final value after the peak, % of |peak|
    bool settled = false;        ///< it stayed within the band for the last fifth of the window at least
};

/// Metrics of `values` sampled at `timesS` for the event at `eventTimeS`. The band is `bandFraction`
/// of the peak deviation: 5 % is the paper's "duration of the transient t_c = 3T" of a first-order
/// link (e^-3 = 0.05). The overshoot is the classical one measured from the largest deviation: for a
/// feed that dips under a load and recovers, how far it goes past its final value on the way back.
/// A swing below 1e-7 of the signal's size (the integrator's accuracy) counts as none (settled at once). Throws
/// std::invalid_argument when the sizes differ, no sample follows the event, or the band is not in (0, 1).
StepMetrics stepMetrics(const std::vector<double>& timesS, const std::vector<double>& values, double eventTimeS,
                        double bandFraction = 0.05);

}  // namespace tt::core
