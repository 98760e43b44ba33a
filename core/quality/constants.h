#pragma once

namespace tt::core {

/// Smallest and largest subgroup size of the X-bar charts (the range of the published tables).
inline constexpr int kMinSubgroupSize = 2;
inline constexpr int kMaxSubgroupSize = 25;

/// The control-chart constants of one subgroup size n (Montgomery, Introduction to Statistical Quality
/// Control, Appendix VI; ASTM STP 15D, Manual on Presentation of Data and Control Chart Analysis).
struct ChartConstants {
    int subgroupSize = 0;         ///< n
    double d2 = 0.0;              ///< E(R)/sigma of a normal sample of n (tabulated)
    double d3 = 0.0;              ///< sd(R)/sigma (tabulated)
    double c4 = 0.0;              ///< E(s)/sigma = sqrt(2/(n-1)) Gamma(n/2)/Gamma((n-1)/2)
    double meanFactorA2 = 0.0;    ///< A2 ~ 3/(d2 sqrt(n)), tabulated: X-bar limits = centre +- A2 R-bar
    double meanFactorA3 = 0.0;    ///< A3 = 3/(c4 sqrt(n)): X-bar limits = centre +- A3 s-bar
    double rangeFactorD3 = 0.0;   ///< D3 ~ max(0, 1 - 3 d3/d2), tabulated: R chart LCL = D3 R-bar
    double rangeFactorD4 = 0.0;   ///< D4 ~ 1 + 3 d3/d2, tabulated: R chart UCL = D4 R-bar
    double stdDevFactorB3 = 0.0;  ///< B3 = max(0, 1 - 3 sqrt(1 - c4^2)/c4): s chart LCL = B3 s-bar
    double stdDevFactorB4 = 0.0;  ///< B4 = 1 + 3 sqrt(1 - c4^2)/c4: s chart UCL = B4 s-bar
};

/// d2(n), the mean of the relative range W = R/sigma of n normal values, n = 2..25, from the published
/// three-decimal table (Montgomery Appendix VI = ASTM STP 15D; Harter 1960, Ann. Math. Stat. 31, to more
/// digits). Throws std::invalid_argument outside 2..25.
double rangeD2(int subgroupSize);

/// d3(n), the standard deviation of W = R/sigma, n = 2..25, from the same published table. Throws
/// std::invalid_argument outside 2..25.
double rangeD3(int subgroupSize);

/// c4(n) = sqrt(2/(n-1)) Gamma(n/2)/Gamma((n-1)/2), the mean of s/sigma for n normal values (Montgomery
/// section 6.3), from Boost.Math's log-gamma; n = 2..1000. Throws std::invalid_argument outside that range.
double stdDevC4(int subgroupSize);

/// Every constant of subgroup size n = 2..25: d2, d3, A2, D3, D4 from the published table (Montgomery
/// Appendix VI), c4 from the gamma function and A3, B3, B4 from c4 by their definitions (Montgomery
/// Section 6.3), which reproduce the published A3, B3, B4. Throws std::invalid_argument outside 2..25.
ChartConstants chartConstants(int subgroupSize);

}  // namespace tt::core
