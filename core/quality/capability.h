#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "core/quality/normality.h"

namespace tt::core {

/// Specification limits of a characteristic, mm (lower < upper; the target lies between them and defaults
/// to their middle).
struct SpecLimits {
    double lowerMm = 0.0;
    double upperMm = 0.0;
    std::optional<double> targetMm;
};

/// How the within-subgroup (short-term) sigma of Cp and Cpk is estimated.
enum class WithinSigmaMethod {
    MovingRange,  ///< MR-bar/d2(2) = MR-bar/1.128 of consecutive individual values
    Range,        ///< R-bar/d2(n) of consecutive subgroups of n
    StdDev,       ///< s-bar/c4(n) of consecutive subgroups of n
};

/// How the indices were computed.
enum class CapabilityMethod {
    Normal,      ///< 6 sigma spreads of a normal distribution (normality not rejected)
    Percentile,  ///< the 0.135 % and 99.865 % quantiles of the data (ISO 22514-2 percentile method)
};

/// The settings of a capability study.
struct CapabilitySettings {
    WithinSigmaMethod within = WithinSigmaMethod::MovingRange;
    int subgroupSize = 1;      ///< n of Range/StdDev, 2..25 (ignored for MovingRange)
    double confidence = 0.95;  ///< level of the two-sided intervals, 0.5 .. 0.999
    double normalityAlpha =
        0.05;  ///< the percentile method is used when the Anderson-Darling p < this (0 .. 0.5; 0 = never)
};

/// A two-sided confidence interval of an index.
struct ConfidenceInterval {
    double lower = 0.0;
    double upper = 0.0;
};

/// The capability and performance indices with their confidence intervals (none for the percentile method,
/// which has no interval formula).
struct CapabilityIndices {
    double cp = 0.0;
    double cpk = 0.0;
    double pp = 0.0;
    double ppk = 0.0;
    std::optional<double> cpm;  ///< Taguchi index; none for the percentile method
    std::optional<ConfidenceInterval> cpInterval;
    std::optional<ConfidenceInterval> cpkInterval;
    std::optional<ConfidenceInterval> cpmInterval;
    std::optional<ConfidenceInterval> ppInterval;
    std::optional<ConfidenceInterval> ppkInterval;
};

/// What the normal indices are computed from.
struct ProcessMoments {
    std::size_t count = 0;        ///< N values
    double meanMm = 0.0;          ///< x-bar
    double sigmaWithinMm = 0.0;   ///< short-term sigma (R-bar/d2, s-bar/c4 or MR-bar/1.128)
    double sigmaOverallMm = 0.0;  ///< sample standard deviation of all N values (N - 1 divisor)
};

/// The empirical quantiles of the percentile method, mm.
struct PercentileSpread {
    double lowerMm = 0.0;   ///< X 0.135 %
    double medianMm = 0.0;  ///< X 50 %
    double upperMm = 0.0;   ///< X 99.865 %
};

/// The result of a capability study of one characteristic.
struct CapabilityStudy {
    std::size_t count = 0;
    double meanMm = 0.0;
    double sigmaWithinMm = 0.0;
    double sigmaOverallMm = 0.0;
    double targetMm = 0.0;
    WithinSigmaMethod within = WithinSigmaMethod::MovingRange;
    int subgroupSize = 1;
    double confidence = 0.95;
    NormalityTest normality;
    CapabilityMethod method = CapabilityMethod::Normal;  ///< which method gave `indices`
    CapabilityIndices indices;
    std::optional<PercentileSpread> percentiles;  ///< the quantiles, when the percentile method was used
    std::size_t belowLower = 0;                   ///< values below the lower specification limit
    std::size_t aboveUpper = 0;                   ///< values above the upper specification limit
};

/// Normal-theory indices (NIST/SEMATECH e-Handbook, section 6.1.6; Montgomery, Introduction to Statistical
/// Quality Control, 6th ed., section 8.3): Cp = (U - L)/(6 sigma_w), Cpk = min(U - x-bar, x-bar - L)/(3
/// sigma_w), Pp and Ppk the same with sigma_o, Cpm = (U - L)/(6 sqrt(sum (x - T)^2/(N - 1))) = (U - L)/(6
/// sqrt(sigma_o^2 + N/(N - 1) (x-bar - T)^2)) (Chan, Cheng & Spiring 1988, JQT 20(3)). Two-sided intervals at
/// `confidence` = 1 - alpha, nu = N - 1: Cp and Pp: C sqrt(chi2(alpha/2; nu)/nu) .. C sqrt(chi2(1 -
/// alpha/2; nu)/nu) (Montgomery section 8.3); Cpk and Ppk: C -+ z(1 - alpha/2) sqrt(1/(9N) + C^2/(2(N - 1)))
/// (Bissell 1990, Applied Statistics 39(3), the normal approximation; Montgomery section 8.3); Cpm: chi-square
/// with nu* = N (1 + a^2)^2/(1 + 2 a^2), a = (x-bar - T)/sigma_o (Boyles 1991, JQT 23(1)). Throws
/// std::invalid_argument on bad limits, N < 2, a sigma not above 0 or a confidence outside 0.5 .. 0.999.
CapabilityIndices normalCapabilityIndices(const ProcessMoments& moments, const SpecLimits& spec,
                                          double confidence = 0.95);

/// Percentile-method indices (ISO 22514-2:2017; Clements 1989, Quality Progress 22(9)): Pp = (U - L)/(X99.865
/// - X0.135), Ppk = min((U - X50)/(X99.865 - X50), (X50 - L)/(X50 - X0.135)); the method does not separate
/// within from overall variation, so Cp = Pp and Cpk = Ppk; no Cpm and no intervals. Throws
/// std::invalid_argument on bad limits or quantiles that are not strictly increasing.
CapabilityIndices percentileCapabilityIndices(const PercentileSpread& spread, const SpecLimits& spec);

/// The within-subgroup sigma of values in production order: MR-bar/1.128 of all consecutive pairs, or
/// R-bar/d2(n) or s-bar/c4(n) of the complete consecutive subgroups of n (a shorter tail is left out).
/// Throws std::invalid_argument on bad values or sizes.
double withinSigma(std::span<const double> valuesMm, WithinSigmaMethod method, int subgroupSize);

/// The fewest values of a capability study (the Anderson-Darling minimum; at least two subgroups as well).
inline constexpr std::size_t kMinCapabilityValues = kMinNormalityValues;

/// A capability study of values in production order: mean, sigma within (settings.within) and overall,
/// the Anderson-Darling test; when its p-value is below settings.normalityAlpha, the percentile method
/// with the quantiles of distributions.h's empiricalQuantile (Hyndman & Fan definition 7) at 0.135 %,
/// 50 % and 99.865 %, otherwise the normal indices with their intervals. With fewer than about 740 values
/// the 0.135 % and 99.865 % quantiles lie between the two most extreme values, so percentile indices from
/// small samples are rough. Throws std::invalid_argument on bad values, limits or settings, too few values,
/// or no scatter.
CapabilityStudy capabilityStudy(std::span<const double> valuesMm, const SpecLimits& spec,
                                const CapabilitySettings& settings = {});

}  // namespace tt::core
