#include "core/control/deflection_compensator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

DeflectionCompensator::DeflectionCompensator(const CompensatorLimits& limits) : m_limits(limits) {
    if (!std::isfinite(limits.maxOffsetMm) || limits.maxOffsetMm <= 0.0)
        throw std::invalid_argument("the largest compensation offset must be above 0 mm");
    if (!std::isfinite(limits.maxRateMmPerS) || limits.maxRateMmPerS <= 0.0)
        throw std::invalid_argument("the compensation rate limit must be above 0 mm/s");
}

CompensationStep DeflectionCompensator::step(double dtS, std::optional<double> deflectionMm) {
    if (!std::isfinite(dtS) || dtS <= 0.0) throw std::invalid_argument("the PLC cycle must be above 0 s");
    CompensationStep out;
    if (!deflectionMm || !std::isfinite(*deflectionMm)) {
        out.holding = true;
        out.targetMm = m_offsetMm;
        out.offsetMm = m_offsetMm;
        return out;
    }
    out.targetMm = -*deflectionMm;
    double target = out.targetMm;
    if (std::abs(target) > m_limits.maxOffsetMm) {
        target = std::copysign(m_limits.maxOffsetMm, target);
        out.rangeLimited = true;
    }
    const double maxStep = m_limits.maxRateMmPerS * dtS;
    const double change = target - m_offsetMm;
    if (std::abs(change) > maxStep) {
        m_offsetMm += std::copysign(maxStep, change);
        out.rateLimited = true;
    } else {
        m_offsetMm = target;
    }
    out.offsetMm = m_offsetMm;
    return out;
}

void DeflectionCompensator::restoreOffset(double offsetMm) {
    if (!std::isfinite(offsetMm)) return;
    m_offsetMm = std::clamp(offsetMm, -m_limits.maxOffsetMm, m_limits.maxOffsetMm);
}

}  // namespace tt::core
