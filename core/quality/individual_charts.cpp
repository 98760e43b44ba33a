#include "core/quality/individual_charts.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/quality/constants.h"
#include "core/quality/series.h"

namespace tt::core {

namespace {

constexpr const char* kChartName = "the individuals chart";

std::vector<double> movingRanges(std::span<const double> values) {
    std::vector<double> ranges(values.size() > 0 ? values.size() - 1 : 0);
    for (std::size_t i = 1; i < values.size(); ++i)
        ranges[i - 1] = std::abs(values[i] - values[i - 1]);
    return ranges;
}

ControlChart assemble(std::span<const double> valuesMm, const ChartLimits& limits) {
    ControlChart chart;
    chart.limits = limits;
    chart.locationMm.assign(valuesMm.begin(), valuesMm.end());
    chart.spreadMm = movingRanges(valuesMm);
    chart.spreadFirstPoint = 1;
    chart.locationBeyondLimits = pointsBeyondLimits(chart.locationMm, limits.location);
    chart.spreadBeyondLimits = pointsBeyondLimits(chart.spreadMm, limits.spread, 1);
    return chart;
}

}  // namespace

ChartLimits individualsLimits(std::span<const double> baselineValuesMm) {
    checkValues(baselineValuesMm, kMinBaselineIndividuals, kChartName);
    const double mean = meanAndDeviation(baselineValuesMm).mean;
    double sumOfRanges = 0.0;
    for (std::size_t i = 1; i < baselineValuesMm.size(); ++i)
        sumOfRanges += std::abs(baselineValuesMm[i] - baselineValuesMm[i - 1]);
    const double meanMovingRange = sumOfRanges / static_cast<double>(baselineValuesMm.size() - 1);
    if (!(meanMovingRange > 0.0))
        throw std::invalid_argument(std::string(kChartName) +
                                    ": every baseline value is the same, so the moving ranges are zero and there "
                                    "are no limits");
    const ChartConstants k = chartConstants(2);
    ChartLimits limits;
    limits.kind = ChartKind::IndividualsMovingRange;
    limits.subgroupSize = 1;
    limits.sigmaWithinMm = meanMovingRange / k.d2;
    limits.locationSigmaMm = limits.sigmaWithinMm;
    limits.location = {mean - 3.0 * limits.sigmaWithinMm, mean, mean + 3.0 * limits.sigmaWithinMm};
    limits.spread = {k.rangeFactorD3 * meanMovingRange, meanMovingRange, k.rangeFactorD4 * meanMovingRange};
    limits.baselinePointCount = baselineValuesMm.size();
    return limits;
}

ControlChart individualsChart(std::span<const double> valuesMm, const ChartLimits& held) {
    if (held.kind != ChartKind::IndividualsMovingRange)
        throw std::invalid_argument("X-bar limits cannot be held on an individuals chart");
    checkHeldLimits(held);
    checkValues(valuesMm, 1, kChartName);
    return assemble(valuesMm, held);
}

ControlChart individualsChart(std::span<const double> valuesMm, const ChartBaseline& baseline) {
    checkValues(valuesMm, kMinBaselineIndividuals, kChartName);
    const ChartBaseline range = resolveBaseline(baseline, valuesMm.size(), kMinBaselineIndividuals, kChartName);
    ChartLimits limits = individualsLimits(valuesMm.subspan(range.firstPoint, range.pointCount));
    limits.baselineFirstPoint = range.firstPoint;
    return assemble(valuesMm, limits);
}

}  // namespace tt::core
