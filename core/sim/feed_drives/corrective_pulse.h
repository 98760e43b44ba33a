#pragma once

#include "core/sim/feed_drives/feed_drives_config.h"

namespace tt::core {

/// Largest pulse amplitude, V (paper 002: corrective voltages within ±0.5 V).
inline constexpr double kMaxPulseAmplitudeV = 0.5;

/// The corrective pulse of paper 002: a rectangular voltage added to one drive's velocity command,
/// fired `leadS` before the programmed velocity change (the paper's p_m = 0.028 s, eq. 4) for a fixed
/// `durationS` (the paper's experiment: 50 ms); only its amplitude varies, chosen by the network.
struct PulseSettings {
    FeedAxis axis = FeedAxis::X;          ///< X needs less amplitude than Z (less inertia, paper 002)
    double leadS = 0.028;                 ///< fired this long before the velocity change, s
    double durationS = 0.050;             ///< length of the pulse, s
    double limitV = kMaxPulseAmplitudeV;  ///< amplitudes are bounded to ±limitV, V
};

/// Throws std::invalid_argument when lead (0 .. 0.2 s), duration (1 ms .. 0.2 s) or the limit
/// (0.01 .. 0.5 V) is out of range.
void validatePulse(const PulseSettings& pulse);

/// The pulse voltage at `timeS` (0 = the velocity change) for `amplitudeV`: amplitude inside
/// [−lead, −lead + duration), 0 elsewhere.
double pulseVoltage(const PulseSettings& pulse, double amplitudeV, double timeS);

}  // namespace tt::core
