#include "core/sim/boring/dither_profile.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {

void requireWithin(double v, double lo, double hi, const char* what) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(std::string(what) + " must be within " + std::to_string(lo) + " .. " +
                                    std::to_string(hi));
}

}  // namespace

DitherProfile::DitherProfile(const DitherConfig& config) : m_config(config) {
    requireWithin(config.amplitudeMm, 0.005, 0.05, "dither amplitude (mm)");
    requireWithin(config.periodS, 0.2, 2.0, "dither period (s)");
    requireWithin(config.constantVelocityFraction, 0.2, 0.9, "dither constant-velocity fraction");
    const double half = config.periodS / 2.0;
    const double accelS = (1.0 - config.constantVelocityFraction) / 2.0 * half;
    const double constS = config.constantVelocityFraction * half;
    // Stroke 2A = V (t_a + t_c): the acceleration and deceleration phases each cover V t_a / 2.
    m_speed = 2.0 * config.amplitudeMm / (accelS + constS);
    m_accel = m_speed / accelS;
    // First stroke (length A, same V and a): t_a + L / V.
    const double fullSpeedLength = m_speed * m_speed / m_accel;
    m_firstStrokeS = config.amplitudeMm >= fullSpeedLength ? accelS + config.amplitudeMm / m_speed
                                                           : 2.0 * std::sqrt(config.amplitudeMm / m_accel);
}

double DitherProfile::plateauDurationS() const {
    return m_config.constantVelocityFraction * m_config.periodS / 2.0;
}

DitherState DitherProfile::stroke(double t, double startMm, double direction, double lengthMm) const {
    // Trapezoid (or triangle when the stroke is too short to reach full speed).
    const double fullLength = m_speed * m_speed / m_accel;
    const double peak = lengthMm >= fullLength ? m_speed : std::sqrt(lengthMm * m_accel);
    const double ta = peak / m_accel;
    const double tc = (lengthMm - peak * ta) / peak;
    DitherState s;
    double travelled = 0.0;
    if (t < ta) {
        s.velocityMmPerS = m_accel * t;
        s.accelerationMmPerS2 = m_accel;
        travelled = 0.5 * m_accel * t * t;
    } else if (t < ta + tc) {
        s.velocityMmPerS = peak;
        travelled = 0.5 * peak * ta + peak * (t - ta);
    } else if (t < 2.0 * ta + tc) {
        const double td = t - ta - tc;
        s.velocityMmPerS = peak - m_accel * td;
        s.accelerationMmPerS2 = -m_accel;
        travelled = 0.5 * peak * ta + peak * tc + peak * td - 0.5 * m_accel * td * td;
    } else {
        travelled = lengthMm;
    }
    s.positionMm = startMm + direction * travelled;
    s.velocityMmPerS *= direction;
    s.accelerationMmPerS2 *= direction;
    return s;
}

DitherState DitherProfile::at(double timeS) const {
    if (timeS <= 0.0) return {};
    const double a = m_config.amplitudeMm;
    if (timeS < m_firstStrokeS) return stroke(timeS, 0.0, -1.0, a);
    const double half = m_config.periodS / 2.0;
    const double since = timeS - m_firstStrokeS;
    const long index = static_cast<long>(std::floor(since / half));
    const double local = since - static_cast<double>(index) * half;
    const bool forward = index % 2 == 0;
    return stroke(local, forward ? -a : a, forward ? 1.0 : -1.0, 2.0 * a);
}

}  // namespace tt::core
