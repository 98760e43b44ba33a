#include "core/quality/capability.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/quality/constants.h"
#include "core/quality/distributions.h"
#include "core/quality/series.h"
#include "core/quality/xbar_charts.h"

namespace tt::core {

namespace {

constexpr double kLowerQuantile = 0.00135;
constexpr double kUpperQuantile = 0.99865;

void checkSpec(const SpecLimits& spec) {
    for (const double v : {spec.lowerMm, spec.upperMm, spec.targetMm.value_or(spec.lowerMm)})
        if (!std::isfinite(v) || std::abs(v) > kMaxAbsMeasurementMm)
            throw std::invalid_argument("the specification limits and target must be finite sizes within +-1e6 mm");
    if (!(spec.lowerMm < spec.upperMm))
        throw std::invalid_argument("the lower specification limit (" + std::to_string(spec.lowerMm) +
                                    " mm) must lie below the upper (" + std::to_string(spec.upperMm) + " mm)");
    if (spec.targetMm && (*spec.targetMm < spec.lowerMm || *spec.targetMm > spec.upperMm))
        throw std::invalid_argument("the target (" + std::to_string(*spec.targetMm) +
                                    " mm) must lie within the specification limits");
}

void checkConfidence(double confidence) {
    if (!(confidence >= 0.5 && confidence <= 0.999))
        throw std::invalid_argument("the confidence level must be 0.5 to 0.999 (got " + std::to_string(confidence) +
                                    ")");
}

double targetOf(const SpecLimits& spec) {
    return spec.targetMm.value_or(0.5 * (spec.lowerMm + spec.upperMm));
}

/// C sqrt(chi2(alpha/2; nu)/nu) .. C sqrt(chi2(1 - alpha/2; nu)/nu).
ConfidenceInterval chiSquareInterval(double index, double dof, double confidence) {
    const double alpha = 1.0 - confidence;
    return {index * std::sqrt(chiSquareQuantile(alpha / 2.0, dof) / dof),
            index * std::sqrt(chiSquareQuantile(1.0 - alpha / 2.0, dof) / dof)};
}

/// Bissell (1990): C -+ z(1 - alpha/2) sqrt(1/(9N) + C^2/(2(N - 1))).
ConfidenceInterval bissellInterval(double index, double count, double confidence) {
    const double z = normalQuantile(0.5 + 0.5 * confidence);
    const double halfWidth = z * std::sqrt(1.0 / (9.0 * count) + index * index / (2.0 * (count - 1.0)));
    return {index - halfWidth, index + halfWidth};
}

double meanMovingRange(std::span<const double> values) {
    double sum = 0.0;
    for (std::size_t i = 1; i < values.size(); ++i)
        sum += std::abs(values[i] - values[i - 1]);
    return sum / static_cast<double>(values.size() - 1);
}

}  // namespace

CapabilityIndices normalCapabilityIndices(const ProcessMoments& moments, const SpecLimits& spec, double confidence) {
    checkSpec(spec);
    checkConfidence(confidence);
    if (moments.count < 2) throw std::invalid_argument("capability indices need at least 2 values");
    if (!(moments.sigmaWithinMm > 0.0) || !(moments.sigmaOverallMm > 0.0) || !std::isfinite(moments.meanMm) ||
        !std::isfinite(moments.sigmaWithinMm) || !std::isfinite(moments.sigmaOverallMm))
        throw std::invalid_argument("capability indices need a finite mean and sigmas above 0 mm (within " +
                                    std::to_string(moments.sigmaWithinMm) + " mm, overall " +
                                    std::to_string(moments.sigmaOverallMm) + " mm)");
    const double width = spec.upperMm - spec.lowerMm;
    const double nearest = std::min(spec.upperMm - moments.meanMm, moments.meanMm - spec.lowerMm);
    const double n = static_cast<double>(moments.count);
    const double dof = n - 1.0;
    const double offTarget = moments.meanMm - targetOf(spec);
    const double so = moments.sigmaOverallMm;

    CapabilityIndices c;
    c.cp = width / (6.0 * moments.sigmaWithinMm);
    c.cpk = nearest / (3.0 * moments.sigmaWithinMm);
    c.pp = width / (6.0 * so);
    c.ppk = nearest / (3.0 * so);
    c.cpm = width / (6.0 * std::sqrt(so * so + n / dof * offTarget * offTarget));
    c.cpInterval = chiSquareInterval(c.cp, dof, confidence);
    c.ppInterval = chiSquareInterval(c.pp, dof, confidence);
    c.cpkInterval = bissellInterval(c.cpk, n, confidence);
    c.ppkInterval = bissellInterval(c.ppk, n, confidence);
    const double a2 = (offTarget / so) * (offTarget / so);
    const double boylesDof = n * (1.0 + a2) * (1.0 + a2) / (1.0 + 2.0 * a2);
    c.cpmInterval = chiSquareInterval(*c.cpm, boylesDof, confidence);
    return c;
}

CapabilityIndices percentileCapabilityIndices(const PercentileSpread& spread, const SpecLimits& spec) {
    checkSpec(spec);
    if (!(spread.lowerMm < spread.medianMm && spread.medianMm < spread.upperMm))
        throw std::invalid_argument("the percentile method needs X0.135 < X50 < X99.865 (got " +
                                    std::to_string(spread.lowerMm) + ", " + std::to_string(spread.medianMm) + ", " +
                                    std::to_string(spread.upperMm) + " mm): too little scatter");
    CapabilityIndices c;
    c.pp = (spec.upperMm - spec.lowerMm) / (spread.upperMm - spread.lowerMm);
    c.ppk = std::min((spec.upperMm - spread.medianMm) / (spread.upperMm - spread.medianMm),
                     (spread.medianMm - spec.lowerMm) / (spread.medianMm - spread.lowerMm));
    c.cp = c.pp;
    c.cpk = c.ppk;
    return c;
}

double withinSigma(std::span<const double> valuesMm, WithinSigmaMethod method, int subgroupSize) {
    if (method == WithinSigmaMethod::MovingRange) {
        checkValues(valuesMm, 2, "the moving-range sigma");
        return meanMovingRange(valuesMm) / rangeD2(2);
    }
    const SubgroupSpread spread = method == WithinSigmaMethod::Range ? SubgroupSpread::Range : SubgroupSpread::StdDev;
    const SubgroupStatistics subgroups = subgroupStatistics(valuesMm, subgroupSize, spread);
    if (subgroups.spreadsMm.size() < kMinBaselineSubgroups)
        throw std::invalid_argument(
            "the within-subgroup sigma needs at least " + std::to_string(kMinBaselineSubgroups) + " subgroups of " +
            std::to_string(subgroupSize) + " (got " + std::to_string(subgroups.spreadsMm.size()) + ")");
    double sum = 0.0;
    for (const double s : subgroups.spreadsMm)
        sum += s;
    const double meanSpread = sum / static_cast<double>(subgroups.spreadsMm.size());
    return method == WithinSigmaMethod::Range ? meanSpread / rangeD2(subgroupSize)
                                              : meanSpread / stdDevC4(subgroupSize);
}

CapabilityStudy capabilityStudy(std::span<const double> valuesMm, const SpecLimits& spec,
                                const CapabilitySettings& settings) {
    checkSpec(spec);
    checkConfidence(settings.confidence);
    if (!(settings.normalityAlpha >= 0.0 && settings.normalityAlpha <= 0.5))
        throw std::invalid_argument("the significance level of the normality test must be 0 to 0.5 (got " +
                                    std::to_string(settings.normalityAlpha) + ")");
    checkValues(valuesMm, kMinCapabilityValues, "the capability study");

    CapabilityStudy study;
    study.count = valuesMm.size();
    study.within = settings.within;
    study.subgroupSize = settings.within == WithinSigmaMethod::MovingRange ? 1 : settings.subgroupSize;
    study.confidence = settings.confidence;
    study.targetMm = targetOf(spec);
    const MeanAndDeviation overall = meanAndDeviation(valuesMm);
    study.meanMm = overall.mean;
    study.sigmaOverallMm = overall.stdDev;

    std::vector<double> sorted(valuesMm.begin(), valuesMm.end());
    std::sort(sorted.begin(), sorted.end());
    study.normality = andersonDarlingNormalitySorted(sorted);  // throws when every value is the same
    study.sigmaWithinMm = withinSigma(valuesMm, settings.within, settings.subgroupSize);
    if (!(study.sigmaWithinMm > 0.0))
        throw std::invalid_argument(
            "the within-subgroup sigma is 0 (every subgroup or consecutive pair is "
            "equal: the gauge resolution is too coarse for the scatter)");
    study.belowLower =
        static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), spec.lowerMm) - sorted.begin());
    study.aboveUpper =
        static_cast<std::size_t>(sorted.end() - std::upper_bound(sorted.begin(), sorted.end(), spec.upperMm));

    if (study.normality.pValue < settings.normalityAlpha) {
        study.method = CapabilityMethod::Percentile;
        study.percentiles = PercentileSpread{empiricalQuantile(sorted, kLowerQuantile), empiricalQuantile(sorted, 0.5),
                                             empiricalQuantile(sorted, kUpperQuantile)};
        study.indices = percentileCapabilityIndices(*study.percentiles, spec);
    } else {
        study.method = CapabilityMethod::Normal;
        study.indices = normalCapabilityIndices({study.count, study.meanMm, study.sigmaWithinMm, study.sigmaOverallMm},
                                                spec, settings.confidence);
    }
    return study;
}

}  // namespace tt::core
