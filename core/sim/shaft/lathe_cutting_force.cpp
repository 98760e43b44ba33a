#include "core/sim/shaft/lathe_cutting_force.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tt::core {

LatheCuttingForce::LatheCuttingForce(const LatheForceModel& model, const LatheCutting& cutting) {
    auto positive = [](double v, const char* what) {
        if (!std::isfinite(v) || v <= 0.0)
            throw std::invalid_argument(std::string(what) + " must be a positive number (got " + std::to_string(v) +
                                        ")");
    };
    positive(model.specificForceNPerMm2, "the specific radial cutting force");
    positive(model.referenceSpeedMPerMin, "the reference cutting speed");
    positive(cutting.feedMmPerRev, "the feed");
    positive(cutting.cuttingSpeedMPerMin, "the cutting speed");
    if (!std::isfinite(model.exponent) || model.exponent < 0.0 || model.exponent >= 1.0)
        throw std::invalid_argument("the Kienzle exponent m must lie in [0, 1) (got " + std::to_string(model.exponent) +
                                    ")");
    if (!std::isfinite(model.speedExponent) || std::abs(model.speedExponent) > 1.0)
        throw std::invalid_argument("the speed exponent must lie in [-1, 1] (got " +
                                    std::to_string(model.speedExponent) + ")");
    if (!std::isfinite(model.leadAngleDeg) || model.leadAngleDeg <= 0.0 || model.leadAngleDeg >= 180.0)
        throw std::invalid_argument("the lead angle must lie between 0 and 180 degrees (got " +
                                    std::to_string(model.leadAngleDeg) + ")");
    const double sinKappa = std::sin(model.leadAngleDeg * std::numbers::pi / 180.0);
    const double h = cutting.feedMmPerRev * sinKappa;
    const double speedFactor =
        std::pow(cutting.cuttingSpeedMPerMin / model.referenceSpeedMPerMin, -model.speedExponent);
    // F_p = k (a / sin κ) h^(1-m) K_v = a · [k h^(1-m) K_v / sin κ]
    m_forcePerDepth = model.specificForceNPerMm2 * std::pow(h, 1.0 - model.exponent) * speedFactor / sinKappa;
}

double LatheCuttingForce::radialForceN(double depthMm) const {
    return depthMm > 0.0 ? m_forcePerDepth * depthMm : 0.0;
}

}  // namespace tt::core
