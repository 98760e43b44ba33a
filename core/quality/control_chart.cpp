#include "core/quality/control_chart.h"

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

std::vector<std::size_t> pointsBeyondLimits(std::span<const double> valuesMm, const ControlLimits& limits,
                                            std::size_t indexOffset) {
    std::vector<std::size_t> beyond;
    for (std::size_t i = 0; i < valuesMm.size(); ++i)
        if (valuesMm[i] < limits.lowerMm || valuesMm[i] > limits.upperMm) beyond.push_back(i + indexOffset);
    return beyond;
}

}  // namespace tt::core
