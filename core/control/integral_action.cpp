#include "core/control/integral_action.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

void IntegralAction::validate() const {
    if (!std::isfinite(weight) || weight < kMinIntegralWeight || weight > kMaxIntegralWeight)
        throw std::invalid_argument("the integral weight must be in " + formatSignificant(kMinIntegralWeight, 3) +
                                    " .. " + formatSignificant(kMaxIntegralWeight, 3) + ", got " +
                                    formatSignificant(weight, 4));
}

RunToRunPlantSpec withIntegralAction(const RunToRunPlantSpec& spec, const IntegralAction& integral) {
    if (!integral.enabled) return spec;
    integral.validate();
    RunToRunPlantSpec out = spec;
    for (std::size_t i = 0; i < out.points.size(); ++i) {
        ControlPointSpec& p = out.points[i];
        const double variance = p.disturbance.stationaryVarianceMm2();
        if (!std::isfinite(variance) || variance <= 0.0)
            throw std::invalid_argument("control point " + std::to_string(i + 1) +
                                        ": its disturbance model already integrates (a random walk); integral "
                                        "action needs a stationary model");
        std::vector<DisturbanceComponent> components = p.disturbance.components();
        components.push_back(DisturbanceComponent::randomWalk(integral.weight * variance));
        p.disturbance = DisturbanceModel(std::move(components));
    }
    return out;
}

}  // namespace tt::core
