#include "core/quality/xbar_charts.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/quality/constants.h"
#include "core/quality/series.h"

namespace tt::core {

namespace {

const char* chartName(SubgroupSpread spread) {
    return spread == SubgroupSpread::Range ? "the X-bar-R chart" : "the X-bar-s chart";
}

double subgroupStdDev(std::span<const double> values, double mean) {
    double sumOfSquares = 0.0;
    for (const double v : values)
        sumOfSquares += (v - mean) * (v - mean);
    return std::sqrt(sumOfSquares / static_cast<double>(values.size() - 1));
}

double meanOf(std::span<const double> values, std::size_t first, std::size_t count) {
    double sum = 0.0;
    for (std::size_t i = first; i < first + count; ++i)
        sum += values[i];
    return sum / static_cast<double>(count);
}

ControlChart assemble(SubgroupStatistics&& subgroups, const ChartLimits& limits) {
    ControlChart chart;
    chart.limits = limits;
    chart.locationBeyondLimits = pointsBeyondLimits(subgroups.meansMm, limits.location);
    chart.spreadBeyondLimits = pointsBeyondLimits(subgroups.spreadsMm, limits.spread);
    chart.locationMm = std::move(subgroups.meansMm);
    chart.spreadMm = std::move(subgroups.spreadsMm);
    chart.unusedValues = subgroups.unusedValues;
    return chart;
}

}  // namespace

SubgroupStatistics subgroupStatistics(std::span<const double> valuesMm, int subgroupSize, SubgroupSpread spread) {
    if (subgroupSize < kMinSubgroupSize || subgroupSize > kMaxSubgroupSize)
        throw std::invalid_argument(std::string(chartName(spread)) + " needs subgroups of " +
                                    std::to_string(kMinSubgroupSize) + " to " + std::to_string(kMaxSubgroupSize) +
                                    " parts (got " + std::to_string(subgroupSize) + ")");
    const auto n = static_cast<std::size_t>(subgroupSize);
    checkValues(valuesMm, n, chartName(spread));
    SubgroupStatistics s;
    s.subgroupSize = subgroupSize;
    s.spread = spread;
    const std::size_t count = valuesMm.size() / n;
    s.unusedValues = valuesMm.size() - count * n;
    s.meansMm.resize(count);
    s.spreadsMm.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const std::span<const double> group = valuesMm.subspan(k * n, n);
        double sum = 0.0;
        double lowest = group[0];
        double highest = group[0];
        for (const double v : group) {
            sum += v;
            lowest = std::min(lowest, v);
            highest = std::max(highest, v);
        }
        const double mean = sum / static_cast<double>(n);
        s.meansMm[k] = mean;
        s.spreadsMm[k] = spread == SubgroupSpread::Range ? highest - lowest : subgroupStdDev(group, mean);
    }
    return s;
}

ChartLimits xbarLimits(const SubgroupStatistics& subgroups, const ChartBaseline& baseline) {
    const std::string name = chartName(subgroups.spread);
    const ChartBaseline range = resolveBaseline(baseline, subgroups.meansMm.size(), kMinBaselineSubgroups, name);
    const double grandMean = meanOf(subgroups.meansMm, range.firstPoint, range.pointCount);
    const double meanSpread = meanOf(subgroups.spreadsMm, range.firstPoint, range.pointCount);
    if (!(meanSpread > 0.0))
        throw std::invalid_argument(name +
                                    ": every baseline subgroup has zero spread (the gauge resolution "
                                    "is too coarse for the scatter), so there are no limits");
    const ChartConstants k = chartConstants(subgroups.subgroupSize);
    ChartLimits limits;
    limits.subgroupSize = subgroups.subgroupSize;
    limits.baselineFirstPoint = range.firstPoint;
    limits.baselinePointCount = range.pointCount;
    double halfWidth = 0.0;
    if (subgroups.spread == SubgroupSpread::Range) {
        limits.kind = ChartKind::XbarRange;
        halfWidth = k.meanFactorA2 * meanSpread;
        limits.spread = {k.rangeFactorD3 * meanSpread, meanSpread, k.rangeFactorD4 * meanSpread};
        limits.sigmaWithinMm = meanSpread / k.d2;
    } else {
        limits.kind = ChartKind::XbarStdDev;
        halfWidth = k.meanFactorA3 * meanSpread;
        limits.spread = {k.stdDevFactorB3 * meanSpread, meanSpread, k.stdDevFactorB4 * meanSpread};
        limits.sigmaWithinMm = meanSpread / k.c4;
    }
    limits.location = {grandMean - halfWidth, grandMean, grandMean + halfWidth};
    limits.locationSigmaMm = halfWidth / 3.0;
    return limits;
}

ChartLimits xbarLimits(std::span<const double> baselineValuesMm, int subgroupSize, SubgroupSpread spread) {
    return xbarLimits(subgroupStatistics(baselineValuesMm, subgroupSize, spread));
}

ControlChart xbarChart(std::span<const double> valuesMm, const ChartLimits& held) {
    if (held.kind == ChartKind::IndividualsMovingRange)
        throw std::invalid_argument("individuals limits cannot be held on an X-bar chart");
    checkHeldLimits(held);
    const SubgroupSpread spread = held.kind == ChartKind::XbarRange ? SubgroupSpread::Range : SubgroupSpread::StdDev;
    return assemble(subgroupStatistics(valuesMm, held.subgroupSize, spread), held);
}

ControlChart xbarChart(std::span<const double> valuesMm, int subgroupSize, SubgroupSpread spread,
                       const ChartBaseline& baseline) {
    SubgroupStatistics subgroups = subgroupStatistics(valuesMm, subgroupSize, spread);
    const ChartLimits limits = xbarLimits(subgroups, baseline);
    return assemble(std::move(subgroups), limits);
}

}  // namespace tt::core
