#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/quality/control_chart.h"

namespace tt::core {

/// The in-control mean and sigma the EWMA and CUSUM charts measure against: given (a target and a known
/// sigma), or estimated from baseline values of the series (their mean; MR-bar/1.128 of their moving ranges).
struct ProcessReference {
    std::optional<double> targetMm;  ///< mu0; none: the baseline mean
    std::optional<double> sigmaMm;   ///< sigma; none: MR-bar/d2(2) of the baseline
    ChartBaseline baseline;          ///< values the estimates come from (all by default)
};

/// A stretch of consecutive points beyond a limit: the chart alarms at `first`.
struct ChartExcursion {
    std::size_t first = 0;
    std::size_t last = 0;
    int side = 0;  ///< +1 above the upper limit, -1 below the lower
};

/// Settings of the EWMA chart (lambda in (0, 1], L in (0, 6]).
struct EwmaSettings {
    double lambda = 0.2;  ///< weight of the newest value
    double widthL = 3.0;  ///< limits at L sigma of the EWMA statistic
    ProcessReference reference;
};

/// The EWMA chart of individual values.
struct EwmaChart {
    double lambda = 0.0;
    double widthL = 0.0;
    double targetMm = 0.0;
    double sigmaMm = 0.0;
    std::vector<double> ewmaMm;   ///< z_i
    std::vector<double> lowerMm;  ///< exact time-varying limits
    std::vector<double> upperMm;
    std::vector<ChartExcursion> excursions;  ///< z_i beyond its limits
};

/// EWMA chart (Roberts 1959; Montgomery, Introduction to Statistical Quality Control, 6th ed., section
/// 9.2): z_i = lambda x_i + (1 - lambda) z_(i-1), z_0 = mu0; limits mu0 +- L sigma sqrt(lambda /
/// (2 - lambda) (1 - (1 - lambda)^(2i))), the exact variance at point i (i = 1, 2, ...), which tends to the
/// asymptotic limits. Throws std::invalid_argument on bad values or settings, or a zero sigma.
EwmaChart ewmaChart(std::span<const double> valuesMm, const EwmaSettings& settings);

/// Settings of the tabular CUSUM (k in [0, 3], h in (0, 20], both in units of sigma; Montgomery recommends
/// k = 0.5 and h = 4 or 5).
struct CusumSettings {
    double k = 0.5;  ///< reference value K = k sigma (half the shift to be detected)
    double h = 5.0;  ///< decision interval H = h sigma
    ProcessReference reference;
};

/// An alarm of the CUSUM: a stretch where C+ (side +1) or C- (side -1) exceeds H.
struct CusumSignal {
    ChartExcursion excursion;
    std::size_t runLength = 0;   ///< N+ or N- at the alarm: consecutive points the sum has been above 0
    std::size_t shiftStart = 0;  ///< first point of that run (the estimated start of the shift)
    double shiftedMeanMm = 0.0;  ///< mu0 + K + C+/N+ or mu0 - K - C-/N- at the alarm (Montgomery section 9.1)
};

/// The tabular CUSUM of individual values.
struct CusumChart {
    double targetMm = 0.0;
    double sigmaMm = 0.0;
    double referenceKMm = 0.0;          ///< K
    double decisionHMm = 0.0;           ///< H
    std::vector<double> upperMm;        ///< C+_i
    std::vector<double> lowerMm;        ///< C-_i
    std::vector<std::size_t> upperRun;  ///< N+_i
    std::vector<std::size_t> lowerRun;  ///< N-_i
    std::vector<CusumSignal> signals;
};

/// Tabular CUSUM (Page 1954; Montgomery, Introduction to Statistical Quality Control, 6th ed.,
/// section 9.1): C+_i = max(0, x_i - (mu0 + K) + C+_(i-1)), C-_i = max(0, (mu0 - K) - x_i + C-_(i-1)), C_0 = 0;
/// an alarm where C+ or C- exceeds H. Throws std::invalid_argument on bad values or settings, or a zero sigma.
CusumChart cusumChart(std::span<const double> valuesMm, const CusumSettings& settings);

}  // namespace tt::core
