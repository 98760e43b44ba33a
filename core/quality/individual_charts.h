#pragma once

#include <cstddef>
#include <span>

#include "core/quality/control_chart.h"

namespace tt::core {

/// The fewest individual values a baseline may hold (one moving range needs two; Montgomery recommends
/// at least 20 to 25).
inline constexpr std::size_t kMinBaselineIndividuals = 2;

/// Phase-I limits of the individuals and moving-range (I-MR) charts from baseline values (Montgomery,
/// Introduction to Statistical Quality Control, 6th ed., section 6.4): MR_i = |x_i - x_(i-1)|, sigma =
/// MR-bar/d2(2) = MR-bar/1.128, individuals x-bar +- 3 MR-bar/1.128, moving ranges 0 .. D4(2) MR-bar =
/// 3.267 MR-bar. Throws std::invalid_argument on bad values, fewer than 2 of them or MR-bar = 0.
ChartLimits individualsLimits(std::span<const double> baselineValuesMm);

/// Phase II: every value against I-MR limits held from an earlier baseline. Throws std::invalid_argument
/// when the limits are not I-MR limits or there are no values.
ControlChart individualsChart(std::span<const double> valuesMm, const ChartLimits& held);

/// Phases I and II in one: limits from the baseline values (moving ranges within the baseline only), held
/// for every value.
ControlChart individualsChart(std::span<const double> valuesMm, const ChartBaseline& baseline = {});

}  // namespace tt::core
