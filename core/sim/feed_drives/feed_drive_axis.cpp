#include "core/sim/feed_drives/feed_drive_axis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void requireRange(double value, double lo, double hi, const char* axis, const char* what, const char* unit) {
    if (!std::isfinite(value) || value < lo || value > hi)
        throw std::invalid_argument(std::string(axis) + ": " + what + " " + formatSignificant(value, 6) +
                                    (*unit != '\0' ? std::string(" ") + unit : std::string()) + " is outside " +
                                    formatSignificant(lo, 6) + " .. " + formatSignificant(hi, 6));
}

// Coulomb friction with the Stribeck rise towards the static level at low speed, N·m (≥ 0).
double slidingFrictionNm(const FeedDriveAxisConfig& c, double speedRadPerS) {
    const double r = speedRadPerS / c.stribeckSpeedRadPerS;
    return c.coulombFrictionNm + (c.staticFrictionNm - c.coulombFrictionNm) * std::exp(-r * r);
}

double signOf(double v) {
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

}  // namespace

void validateFeedDriveAxis(const FeedDriveAxisConfig& c, const char* axis) {
    requireRange(c.inertiaKgM2, 1e-6, 10.0, axis, "inertia", "kg·m²");
    requireRange(c.torqueConstantNmPerA, 1e-3, 100.0, axis, "torque constant", "N·m/A");
    requireRange(c.currentLimitA, 0.1, 1000.0, axis, "current limit", "A");
    requireRange(c.viscousFrictionNmSPerRad, 0.0, 100.0, axis, "viscous friction", "N·m·s/rad");
    requireRange(c.coulombFrictionNm, 0.0, 1000.0, axis, "Coulomb friction", "N·m");
    requireRange(c.staticFrictionNm, c.coulombFrictionNm, 1000.0, axis, "static friction (at least the Coulomb)",
                 "N·m");
    requireRange(c.stribeckSpeedRadPerS, 1e-3, 100.0, axis, "Stribeck speed", "rad/s");
    requireRange(c.screwLeadMm, 0.1, 100.0, axis, "screw lead", "mm");
    requireRange(c.encoderStepMm, 1e-6, 0.1, axis, "encoder step", "mm");
    requireRange(c.positionGainPerS, 0.1, 1000.0, axis, "position loop gain", "1/s");
    requireRange(c.speedPerVoltRadPerSPerV, 0.01, 1000.0, axis, "speed per volt", "rad/s/V");
    requireRange(c.commandLimitV, 0.1, 100.0, axis, "command range", "V");
    requireRange(c.velocityGainAPerRadPerS, 1e-4, 1000.0, axis, "velocity loop gain", "A per rad/s");
    requireRange(c.velocityIntegralTimeS, 0.0, 10.0, axis, "velocity loop integral time", "s");
    requireRange(c.velocityGainFactor, 0.1, 10.0, axis, "velocity gain factor", "");
    const double peakNm = c.torqueConstantNmPerA * c.currentLimitA;
    if (c.coulombFrictionNm >= peakNm)
        throw std::invalid_argument(
            std::string(axis) + ": Coulomb friction " + formatSignificant(c.coulombFrictionNm, 6) +
            " N·m is not below the torque at the current limit (" + formatSignificant(peakNm, 6) + " N·m)");
    if (c.staticFrictionNm >= peakNm)
        throw std::invalid_argument(std::string(axis) + ": static friction " +
                                    formatSignificant(c.staticFrictionNm, 6) +
                                    " N·m is not below the torque at the current limit (" +
                                    formatSignificant(peakNm, 6) + " N·m): the motor could never break away");
}

double motorSpeedRadPerS(const FeedDriveAxisConfig& config, double slideMmPerS) {
    return kTwoPi * slideMmPerS / config.screwLeadMm;
}

double slideSpeedMmPerS(const FeedDriveAxisConfig& config, double motorRadPerS) {
    return motorRadPerS * config.screwLeadMm / kTwoPi;
}

FeedDriveAxis::FeedDriveAxis(const FeedDriveAxisConfig& config, double positionMm) : m_config(config) {
    validateFeedDriveAxis(config, "axis");
    m_angleRad = kTwoPi * positionMm / config.screwLeadMm;
}

void FeedDriveAxis::settleOnRamp(double commandMm, double slideMmPerS) {
    const FeedDriveAxisConfig& c = m_config;
    m_speed = motorSpeedRadPerS(c, slideMmPerS);
    m_stuck = m_speed == 0.0;
    const double frictionNm =
        m_stuck ? 0.0 : signOf(m_speed) * slidingFrictionNm(c, m_speed) + c.viscousFrictionNmSPerRad * m_speed;
    m_current = frictionNm / c.torqueConstantNmPerA;
    // PI: the integrator holds the current, no speed error. P only: the speed error carries it.
    const double speedErrorRadPerS = c.velocityIntegralTimeS > 0.0 ? 0.0 : m_current / c.velocityGainAPerRadPerS;
    m_integralRadPerS = c.velocityIntegralTimeS > 0.0 ? m_current / c.velocityGainAPerRadPerS : 0.0;
    const double commandRadPerS = m_speed + speedErrorRadPerS;
    // The CNC asks for commandRadPerS / factor in its own scaling; its following error is that over Kv.
    const double followingMm = slideSpeedMmPerS(c, commandRadPerS / c.velocityGainFactor) / c.positionGainPerS;
    m_angleRad = kTwoPi * (commandMm - followingMm) / c.screwLeadMm;
    m_commandV = commandRadPerS / (c.speedPerVoltRadPerSPerV * c.velocityGainFactor);
}

void FeedDriveAxis::step(double dtS, double commandMm, double extraV, double loadTorqueNm) {
    const FeedDriveAxisConfig& c = m_config;
    // CNC position loop on the encoder, analog output within its range, plus the extra command.
    const double cncV =
        motorSpeedRadPerS(c, c.positionGainPerS * (commandMm - encoderMm())) / c.speedPerVoltRadPerSPerV;
    m_commandV = std::clamp(cncV + extraV, -c.commandLimitV, c.commandLimitV);
    // PI velocity loop with the current limit; the integrator stops while the limit holds it back.
    const double speedError = m_commandV * c.speedPerVoltRadPerSPerV * c.velocityGainFactor - m_speed;
    const double wanted = c.velocityGainAPerRadPerS * (speedError + m_integralRadPerS);
    m_current = std::clamp(wanted, -c.currentLimitA, c.currentLimitA);
    if (c.velocityIntegralTimeS > 0.0 && (m_current == wanted || signOf(speedError) != signOf(wanted)))
        m_integralRadPerS += dtS * speedError / c.velocityIntegralTimeS;
    // Motor with Karnopp friction.
    const double drivingNm = c.torqueConstantNmPerA * m_current - loadTorqueNm;
    if (m_stuck && std::abs(drivingNm) <= c.staticFrictionNm) {
        m_speed = 0.0;
    } else {
        const double before = m_speed;
        const double direction = m_stuck ? signOf(drivingNm) : signOf(m_speed);
        m_speed += dtS * (drivingNm - frictionTorqueNm(direction)) / c.inertiaKgM2;
        m_stuck = false;
        if (m_speed * direction <= 0.0 && before * direction >= 0.0) {  // through zero: stops and sticks
            m_speed = 0.0;
            m_stuck = true;
        }
    }
    m_angleRad += dtS * m_speed;
}

double FeedDriveAxis::frictionTorqueNm(double direction) const {
    return direction * slidingFrictionNm(m_config, m_speed) + m_config.viscousFrictionNmSPerRad * m_speed;
}

double FeedDriveAxis::positionMm() const {
    return m_angleRad * m_config.screwLeadMm / kTwoPi;
}

double FeedDriveAxis::encoderMm() const {
    return m_config.encoderStepMm * std::floor(positionMm() / m_config.encoderStepMm);
}

}  // namespace tt::core
