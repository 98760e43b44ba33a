#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/quality/control_chart.h"

namespace tt::core {

/// How the scatter within a subgroup is measured.
enum class SubgroupSpread {
    Range,   ///< R = max - min (X-bar-R; sigma = R-bar/d2)
    StdDev,  ///< s with the n - 1 divisor (X-bar-s; sigma = s-bar/c4)
};

/// The fewest subgroups a baseline may hold (Montgomery recommends 20 to 25 for trustworthy limits).
inline constexpr std::size_t kMinBaselineSubgroups = 2;

/// Means and spreads of consecutive subgroups of n values: subgroup k is values k*n .. k*n + n - 1; the
/// values after the last complete subgroup are left out and counted.
struct SubgroupStatistics {
    int subgroupSize = 0;
    SubgroupSpread spread = SubgroupSpread::Range;
    std::vector<double> meansMm;
    std::vector<double> spreadsMm;  ///< ranges or standard deviations, mm
    std::size_t unusedValues = 0;
};

/// The subgroup means and ranges (or standard deviations) of the values, n = 2..25. Throws
/// std::invalid_argument on a bad size or value (checkValues) or fewer than n values.
SubgroupStatistics subgroupStatistics(std::span<const double> valuesMm, int subgroupSize, SubgroupSpread spread);

/// Phase-I limits from the baseline subgroups of `subgroups` (Montgomery, Introduction to Statistical
/// Quality Control, 6th ed., sections 6.2 and 6.3): X-bar-R: x-double-bar +- A2 R-bar, R chart
/// D3 R-bar .. D4 R-bar, sigma = R-bar/d2; X-bar-s: x-double-bar +- A3 s-bar, s chart B3 s-bar ..
/// B4 s-bar, sigma = s-bar/c4. Throws std::invalid_argument on a bad baseline or a zero mean spread.
ChartLimits xbarLimits(const SubgroupStatistics& subgroups, const ChartBaseline& baseline = {});

/// Phase-I limits from baseline values alone (all their complete subgroups of n).
ChartLimits xbarLimits(std::span<const double> baselineValuesMm, int subgroupSize, SubgroupSpread spread);

/// Phase II: every subgroup of the values against limits held from an earlier baseline (X-bar-R or X-bar-s
/// limits, whose subgroup size and spread the chart takes). Throws std::invalid_argument when the limits
/// are not X-bar limits or fewer than n values are given.
ControlChart xbarChart(std::span<const double> valuesMm, const ChartLimits& held);

/// Phases I and II in one: limits from the baseline subgroups of the values, held for all of them.
ControlChart xbarChart(std::span<const double> valuesMm, int subgroupSize, SubgroupSpread spread,
                       const ChartBaseline& baseline = {});

}  // namespace tt::core
