#include "core/sim/boring/cross_feed_drive.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {

// N / kg = m/s² = 1000 mm/s².
constexpr double kMmPerM = 1000.0;

void requirePositive(double v, const char* what) {
    if (!std::isfinite(v) || v <= 0.0) throw std::invalid_argument(std::string(what) + " must be above 0");
}

void requireNonNegative(double v, const char* what) {
    if (!std::isfinite(v) || v < 0.0) throw std::invalid_argument(std::string(what) + " must not be negative");
}

}  // namespace

CrossFeedDrive::CrossFeedDrive(const CrossFeedDriveConfig& config, unsigned long long seed)
    : m_config(config), m_rng(seed) {
    requirePositive(config.slideMassKg, "slide mass");
    requireNonNegative(config.motorInertiaKg, "motor inertia");
    requireNonNegative(config.coulombFrictionN, "Coulomb friction");
    requireNonNegative(config.viscousFrictionNsPerMm, "viscous friction");
    requirePositive(config.transmissionStiffnessNPerMm, "transmission stiffness");
    requireNonNegative(config.transmissionDampingNsPerMm, "transmission damping");
    requirePositive(config.currentToForceNPerA, "k_p");
    requireNonNegative(config.currentNoiseA, "current noise");
    requireNonNegative(config.velocityNoiseMmPerS, "velocity noise");
    requireNonNegative(config.positionNoiseMm, "position noise");
    if (!std::isfinite(config.staticFrictionN) || config.staticFrictionN < config.coulombFrictionN)
        throw std::invalid_argument("static friction must be at least the Coulomb friction");
}

void CrossFeedDrive::step(double dtS, const MotorCommand& command, double externalForceN) {
    const CrossFeedDriveConfig& c = m_config;
    const double transmission = c.transmissionStiffnessNPerMm * (command.positionMm - m_slideMm) +
                                c.transmissionDampingNsPerMm * (command.velocityMmPerS - m_slideVelocity);
    const double driving = transmission + externalForceN;  // everything but friction
    // Karnopp friction: a stuck slide stays stuck while the driving force is below breakaway.
    if (m_stuck && std::abs(driving) <= c.staticFrictionN) {
        m_slideVelocity = 0.0;
    } else {
        const double direction = m_stuck ? (driving > 0.0 ? 1.0 : -1.0) : (m_slideVelocity > 0.0 ? 1.0 : -1.0);
        const double friction = direction * c.coulombFrictionN + c.viscousFrictionNsPerMm * m_slideVelocity;
        const double before = m_slideVelocity;
        m_slideVelocity += dtS * (driving - friction) / c.slideMassKg * kMmPerM;
        m_stuck = false;
        // Velocity through zero: the slide stops and sticks unless pushed past breakaway next step.
        if ((before > 0.0 && m_slideVelocity <= 0.0) || (before < 0.0 && m_slideVelocity >= 0.0) ||
            (before == 0.0 && m_slideVelocity * direction <= 0.0)) {
            m_slideVelocity = 0.0;
            m_stuck = true;
        }
    }
    m_slideMm += dtS * m_slideVelocity;
    m_motorForceN = transmission + c.motorInertiaKg * command.accelerationMmPerS2 / kMmPerM;
}

DriveSample CrossFeedDrive::sample(double timeS) {
    DriveSample s;
    s.timeS = timeS;
    s.currentA = currentA() + m_config.currentNoiseA * m_normal(m_rng);
    s.velocityMmPerS = m_slideVelocity + m_config.velocityNoiseMmPerS * m_normal(m_rng);
    s.positionMm = m_slideMm + m_config.positionNoiseMm * m_normal(m_rng);
    return s;
}

}  // namespace tt::core
