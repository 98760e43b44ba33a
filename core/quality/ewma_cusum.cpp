#include "core/quality/ewma_cusum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/quality/constants.h"
#include "core/quality/series.h"

namespace tt::core {

namespace {

struct Reference {
    double targetMm = 0.0;
    double sigmaMm = 0.0;
};

void checkFinite(const std::optional<double>& value, const std::string& what) {
    if (value && (!std::isfinite(*value) || std::abs(*value) > kMaxAbsMeasurementMm))
        throw std::invalid_argument(what + " must be a finite size within +-1e6 mm");
}

Reference resolveReference(std::span<const double> valuesMm, const ProcessReference& reference,
                           const std::string& chartName) {
    checkValues(valuesMm, 1, chartName);
    checkFinite(reference.targetMm, chartName + ": the target");
    checkFinite(reference.sigmaMm, chartName + ": sigma");
    Reference resolved;
    if (reference.targetMm && reference.sigmaMm) {
        resolved = {*reference.targetMm, *reference.sigmaMm};
    } else {
        const ChartBaseline range = resolveBaseline(reference.baseline, valuesMm.size(), 2, chartName);
        const std::span<const double> baseline = valuesMm.subspan(range.firstPoint, range.pointCount);
        resolved.targetMm = reference.targetMm ? *reference.targetMm : meanAndDeviation(baseline).mean;
        if (reference.sigmaMm) {
            resolved.sigmaMm = *reference.sigmaMm;
        } else {
            double sumOfRanges = 0.0;
            for (std::size_t i = 1; i < baseline.size(); ++i)
                sumOfRanges += std::abs(baseline[i] - baseline[i - 1]);
            resolved.sigmaMm = sumOfRanges / static_cast<double>(baseline.size() - 1) / rangeD2(2);
        }
    }
    if (!(resolved.sigmaMm > 0.0))
        throw std::invalid_argument(chartName + ": sigma must be above 0 mm (got " + std::to_string(resolved.sigmaMm) +
                                    " mm)");
    return resolved;
}

/// Groups consecutive flagged points (side +1 / -1, 0 = inside) into excursions.
void addToExcursions(std::vector<ChartExcursion>& excursions, std::size_t i, int side) {
    if (side == 0) return;
    if (!excursions.empty() && excursions.back().last + 1 == i && excursions.back().side == side) {
        excursions.back().last = i;
        return;
    }
    excursions.push_back({i, i, side});
}

constexpr std::size_t kNoSignal = std::numeric_limits<std::size_t>::max();

/// Opens a CUSUM signal where the sum first exceeds H and extends it while it stays above.
void trackSignal(std::vector<CusumSignal>& signals, std::size_t& open, std::size_t i, bool beyond, int side,
                 std::size_t run, double sumMm, double referenceMm) {
    if (!beyond) {
        open = kNoSignal;
        return;
    }
    if (open != kNoSignal) {
        signals[open].excursion.last = i;
        return;
    }
    open = signals.size();
    const double shiftedMeanMm = referenceMm + static_cast<double>(side) * sumMm / static_cast<double>(run);
    signals.push_back({{i, i, side}, run, i + 1 - run, shiftedMeanMm});
}

}  // namespace

EwmaChart ewmaChart(std::span<const double> valuesMm, const EwmaSettings& settings) {
    if (!(settings.lambda > 0.0 && settings.lambda <= 1.0))
        throw std::invalid_argument("the EWMA weight lambda must lie in (0, 1] (got " +
                                    std::to_string(settings.lambda) + ")");
    if (!(settings.widthL > 0.0 && settings.widthL <= 6.0))
        throw std::invalid_argument("the EWMA limit width L must lie in (0, 6] sigma (got " +
                                    std::to_string(settings.widthL) + ")");
    const Reference reference = resolveReference(valuesMm, settings.reference, "the EWMA chart");
    EwmaChart chart;
    chart.lambda = settings.lambda;
    chart.widthL = settings.widthL;
    chart.targetMm = reference.targetMm;
    chart.sigmaMm = reference.sigmaMm;
    const std::size_t n = valuesMm.size();
    chart.ewmaMm.resize(n);
    chart.lowerMm.resize(n);
    chart.upperMm.resize(n);
    const double lambda = settings.lambda;
    const double asymptoticVariance = lambda / (2.0 - lambda);
    const double decaySquared = (1.0 - lambda) * (1.0 - lambda);
    const double asymptoticHalfWidth = settings.widthL * reference.sigmaMm * std::sqrt(asymptoticVariance);
    double z = reference.targetMm;
    double decayPower = 1.0;  // (1 - lambda)^(2i); below 1e-17 the factor 1 - (1 - lambda)^(2i) is 1 in double
    for (std::size_t i = 0; i < n; ++i) {
        z = lambda * valuesMm[i] + (1.0 - lambda) * z;
        double halfWidth = asymptoticHalfWidth;
        if (decayPower > 1e-17) {
            decayPower *= decaySquared;
            halfWidth = asymptoticHalfWidth * std::sqrt(1.0 - decayPower);
        }
        chart.ewmaMm[i] = z;
        chart.lowerMm[i] = reference.targetMm - halfWidth;
        chart.upperMm[i] = reference.targetMm + halfWidth;
        addToExcursions(chart.excursions, i, z > chart.upperMm[i] ? 1 : (z < chart.lowerMm[i] ? -1 : 0));
    }
    return chart;
}

CusumChart cusumChart(std::span<const double> valuesMm, const CusumSettings& settings) {
    if (!(settings.k >= 0.0 && settings.k <= 3.0))
        throw std::invalid_argument("the CUSUM reference value k must lie in [0, 3] sigma (got " +
                                    std::to_string(settings.k) + ")");
    if (!(settings.h > 0.0 && settings.h <= 20.0))
        throw std::invalid_argument("the CUSUM decision interval h must lie in (0, 20] sigma (got " +
                                    std::to_string(settings.h) + ")");
    const Reference reference = resolveReference(valuesMm, settings.reference, "the CUSUM chart");
    CusumChart chart;
    chart.targetMm = reference.targetMm;
    chart.sigmaMm = reference.sigmaMm;
    chart.referenceKMm = settings.k * reference.sigmaMm;
    chart.decisionHMm = settings.h * reference.sigmaMm;
    const std::size_t n = valuesMm.size();
    chart.upperMm.resize(n);
    chart.lowerMm.resize(n);
    chart.upperRun.resize(n);
    chart.lowerRun.resize(n);
    const double upperReference = reference.targetMm + chart.referenceKMm;
    const double lowerReference = reference.targetMm - chart.referenceKMm;
    double upper = 0.0;
    double lower = 0.0;
    std::size_t upperRun = 0;
    std::size_t lowerRun = 0;
    std::size_t openUpper = kNoSignal;  // index in chart.signals of the alarm still going on, if any
    std::size_t openLower = kNoSignal;
    for (std::size_t i = 0; i < n; ++i) {
        upper = std::max(0.0, valuesMm[i] - upperReference + upper);
        lower = std::max(0.0, lowerReference - valuesMm[i] + lower);
        upperRun = upper > 0.0 ? upperRun + 1 : 0;
        lowerRun = lower > 0.0 ? lowerRun + 1 : 0;
        chart.upperMm[i] = upper;
        chart.lowerMm[i] = lower;
        chart.upperRun[i] = upperRun;
        chart.lowerRun[i] = lowerRun;
        trackSignal(chart.signals, openUpper, i, upper > chart.decisionHMm, 1, upperRun, upper, upperReference);
        trackSignal(chart.signals, openLower, i, lower > chart.decisionHMm, -1, lowerRun, lower, lowerReference);
    }
    return chart;
}

}  // namespace tt::core
