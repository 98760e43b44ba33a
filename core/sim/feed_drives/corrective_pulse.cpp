#include "core/sim/feed_drives/corrective_pulse.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

void requireRange(double v, double lo, double hi, const char* what, const char* unit, double scale) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(std::string("pulse ") + what + " " + formatSignificant(v * scale, 6) + " " + unit +
                                    " is outside " + formatSignificant(lo * scale, 6) + " .. " +
                                    formatSignificant(hi * scale, 6) + " " + unit);
}

}  // namespace

void validatePulse(const PulseSettings& p) {
    requireRange(p.leadS, 0.0, 0.2, "lead", "ms", 1e3);
    requireRange(p.durationS, 0.001, 0.2, "duration", "ms", 1e3);
    requireRange(p.limitV, 0.01, kMaxPulseAmplitudeV, "amplitude limit", "V", 1.0);
}

double pulseVoltage(const PulseSettings& pulse, double amplitudeV, double timeS) {
    const double start = -pulse.leadS;
    return timeS >= start && timeS < start + pulse.durationS ? amplitudeV : 0.0;
}

}  // namespace tt::core
