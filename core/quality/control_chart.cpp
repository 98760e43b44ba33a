#include "core/quality/control_chart.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

ChartBaseline resolveBaseline(const ChartBaseline& baseline, std::size_t pointCount, std::size_t minimumPoints,
                              const std::string& chartName) {
    if (baseline.firstPoint >= pointCount)
        throw std::invalid_argument(chartName + ": the baseline starts at point " +
                                    std::to_string(baseline.firstPoint + 1) + " but the chart has " +
                                    std::to_string(pointCount) + " points");
    const std::size_t available = pointCount - baseline.firstPoint;
    ChartBaseline resolved{baseline.firstPoint, baseline.pointCount == 0 ? available : baseline.pointCount};
    if (resolved.pointCount > available)
        throw std::invalid_argument(chartName + ": the baseline of " + std::to_string(resolved.pointCount) +
                                    " points from point " + std::to_string(baseline.firstPoint + 1) +
                                    " reaches past the chart's " + std::to_string(pointCount) + " points");
    if (resolved.pointCount < minimumPoints)
        throw std::invalid_argument(chartName + ": the baseline needs at least " + std::to_string(minimumPoints) +
                                    " points (got " + std::to_string(resolved.pointCount) + ")");
    return resolved;
}

void checkHeldLimits(const ChartLimits& limits) {
    const bool individuals = limits.kind == ChartKind::IndividualsMovingRange;
    if (individuals ? limits.subgroupSize != 1 : (limits.subgroupSize < 2 || limits.subgroupSize > 25))
        throw std::invalid_argument("held chart limits with subgroup size " + std::to_string(limits.subgroupSize) +
                                    (individuals ? " (individuals charts have 1)" : " (X-bar charts need 2 to 25)"));
    for (const ControlLimits& l : {limits.location, limits.spread}) {
        if (!std::isfinite(l.lowerMm) || !std::isfinite(l.centreMm) || !std::isfinite(l.upperMm))
            throw std::invalid_argument("held chart limits must be finite numbers");
        if (!(l.lowerMm <= l.centreMm && l.centreMm <= l.upperMm))
            throw std::invalid_argument("held chart limits must have lower <= centre <= upper (got " +
                                        std::to_string(l.lowerMm) + ", " + std::to_string(l.centreMm) + ", " +
                                        std::to_string(l.upperMm) + " mm)");
    }
    if (!(limits.sigmaWithinMm > 0.0 && std::isfinite(limits.sigmaWithinMm)) ||
        !(limits.locationSigmaMm > 0.0 && std::isfinite(limits.locationSigmaMm)))
        throw std::invalid_argument("held chart limits need sigmas above 0 mm");
}

std::vector<std::size_t> pointsBeyondLimits(std::span<const double> valuesMm, const ControlLimits& limits,
                                            std::size_t indexOffset) {
    std::vector<std::size_t> beyond;
    for (std::size_t i = 0; i < valuesMm.size(); ++i)
        if (valuesMm[i] < limits.lowerMm || valuesMm[i] > limits.upperMm) beyond.push_back(i + indexOffset);
    return beyond;
}

}  // namespace tt::core
