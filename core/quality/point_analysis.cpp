#include "core/quality/point_analysis.h"

#include "core/quality/individual_charts.h"

#include <future>

namespace tt::core {

namespace {

/// From this many values the capability study runs on a thread of its own beside the rule scan.
constexpr std::size_t kParallelCapabilityValues = 100000;

ControlChart chartOf(std::span<const double> values, const PointAnalysisSettings& settings) {
    if (settings.heldLimits)
        return settings.heldLimits->kind == ChartKind::IndividualsMovingRange
                   ? individualsChart(values, *settings.heldLimits)
                   : xbarChart(values, *settings.heldLimits);
    if (settings.subgroupSize == 1) return individualsChart(values, settings.baseline);
    return xbarChart(values, settings.subgroupSize, settings.spread, settings.baseline);
}

WithinSigmaMethod withinMethodOf(const ChartLimits& limits) {
    switch (limits.kind) {
        case ChartKind::XbarRange:
            return WithinSigmaMethod::Range;
        case ChartKind::XbarStdDev:
            return WithinSigmaMethod::StdDev;
        case ChartKind::IndividualsMovingRange:
            break;
    }
    return WithinSigmaMethod::MovingRange;
}

}  // namespace

PointAnalysis analysePoint(const MeasuredSeries& series, const PointAnalysisSettings& settings) {
    checkSeries(series, 1, "the analysis of a control point");
    PointAnalysis result;
    const std::span<const double> values = series.valuesMm;
    const MeanAndDeviation moments = meanAndDeviation(values);
    result.count = moments.count;
    result.meanMm = moments.mean;
    result.sigmaOverallMm = moments.stdDev;
    result.firstPart = series.partNumbers.front();
    result.lastPart = series.partNumbers.back();
    result.firstTimeS = series.timesS.front();
    result.lastTimeS = series.timesS.back();

    result.chart = chartOf(values, settings);
    const ChartLimits& limits = result.chart.limits;
    // The capability study (a sort and the normality test of every value) runs beside the rule scan: over a
    // million readings each is a tenth of a second (docs/BENCHMARKS.md, "The plant-wide history").
    std::future<CapabilityStudy> capability;
    if (settings.spec) {
        CapabilitySettings study;
        study.within = withinMethodOf(limits);
        study.subgroupSize = limits.subgroupSize;
        study.confidence = settings.confidence;
        study.normalityAlpha = settings.normalityAlpha;
        capability =
            std::async(values.size() >= kParallelCapabilityValues ? std::launch::async : std::launch::deferred,
                       [values, spec = *settings.spec, study] { return capabilityStudy(values, spec, study); });
    }
    for (RuleViolation& v : findRuleViolations(result.chart.locationMm, limits.location.centreMm,
                                               limits.locationSigmaMm, settings.rules)) {
        std::vector<std::int64_t> parts = partsOfPoints(series, limits.subgroupSize, v.points);
        result.violations.push_back({std::move(v), std::move(parts)});
    }
    if (capability.valid()) result.capability = capability.get();
    return result;
}

}  // namespace tt::core
