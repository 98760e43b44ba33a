#include "core/quality/constants.h"

#include <algorithm>
#include <array>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

constexpr int kMaxC4SubgroupSize = 1000;

// Montgomery, Introduction to Statistical Quality Control (6th ed., 2009), Appendix VI "Factors for
// constructing variables control charts", n = 2..25 (the ASTM STP 15D values): d2, d3 and the range-chart
// factors A2, D3, D4, typed from the table, so charts match the books and the tools that use them to the
// last printed digit. tests/core/quality checks them against the distribution of the range integrated
// numerically (the printed D3, D4 were computed from three-decimal d2, d3 and differ from the exact
// values by up to 0.0009; d3(19) is printed 0.734 for the exact 0.73348).
constexpr std::array<double, 24> kD2 = {1.128, 1.693, 2.059, 2.326, 2.534, 2.704, 2.847, 2.970,
                                        3.078, 3.173, 3.258, 3.336, 3.407, 3.472, 3.532, 3.588,
                                        3.640, 3.689, 3.735, 3.778, 3.819, 3.858, 3.895, 3.931};
constexpr std::array<double, 24> kD3 = {0.853, 0.888, 0.880, 0.864, 0.848, 0.833, 0.820, 0.808,
                                        0.797, 0.787, 0.778, 0.770, 0.763, 0.756, 0.750, 0.744,
                                        0.739, 0.734, 0.729, 0.724, 0.720, 0.716, 0.712, 0.708};
constexpr std::array<double, 24> kA2 = {1.880, 1.023, 0.729, 0.577, 0.483, 0.419, 0.373, 0.337,
                                        0.308, 0.285, 0.266, 0.249, 0.235, 0.223, 0.212, 0.203,
                                        0.194, 0.187, 0.180, 0.173, 0.167, 0.162, 0.157, 0.153};
constexpr std::array<double, 24> kD3Factor = {0.0,   0.0,   0.0,   0.0,   0.0,   0.076, 0.136, 0.184,
                                              0.223, 0.256, 0.283, 0.307, 0.328, 0.347, 0.363, 0.378,
                                              0.391, 0.403, 0.415, 0.425, 0.434, 0.443, 0.451, 0.459};
constexpr std::array<double, 24> kD4Factor = {3.267, 2.574, 2.282, 2.114, 2.004, 1.924, 1.864, 1.816,
                                              1.777, 1.744, 1.717, 1.693, 1.672, 1.653, 1.637, 1.622,
                                              1.608, 1.597, 1.585, 1.575, 1.566, 1.557, 1.548, 1.541};

void checkTableSize(int n) {
    if (n < kMinSubgroupSize || n > kMaxSubgroupSize)
        throw std::invalid_argument("the subgroup size must be " + std::to_string(kMinSubgroupSize) + " to " +
                                    std::to_string(kMaxSubgroupSize) + " parts (got " + std::to_string(n) + ")");
}

}  // namespace

double rangeD2(int subgroupSize) {
    checkTableSize(subgroupSize);
    return kD2[static_cast<std::size_t>(subgroupSize - kMinSubgroupSize)];
}

double rangeD3(int subgroupSize) {
    checkTableSize(subgroupSize);
    return kD3[static_cast<std::size_t>(subgroupSize - kMinSubgroupSize)];
}

double stdDevC4(int subgroupSize) {
    if (subgroupSize < 2 || subgroupSize > kMaxC4SubgroupSize)
        throw std::invalid_argument("c4 is defined here for 2 to " + std::to_string(kMaxC4SubgroupSize) +
                                    " values (got " + std::to_string(subgroupSize) + ")");
    const double n = static_cast<double>(subgroupSize);
    return std::sqrt(2.0 / (n - 1.0)) * std::exp(boost::math::lgamma(n / 2.0) - boost::math::lgamma((n - 1.0) / 2.0));
}

ChartConstants chartConstants(int subgroupSize) {
    ChartConstants k;
    k.subgroupSize = subgroupSize;
    const auto row = static_cast<std::size_t>(subgroupSize - kMinSubgroupSize);
    k.d2 = rangeD2(subgroupSize);
    k.d3 = rangeD3(subgroupSize);
    k.c4 = stdDevC4(subgroupSize);
    k.meanFactorA2 = kA2[row];
    k.rangeFactorD3 = kD3Factor[row];
    k.rangeFactorD4 = kD4Factor[row];
    k.meanFactorA3 = 3.0 / (k.c4 * std::sqrt(static_cast<double>(subgroupSize)));
    const double relativeSdOfS = std::sqrt(1.0 - k.c4 * k.c4) / k.c4;
    k.stdDevFactorB3 = std::max(0.0, 1.0 - 3.0 * relativeSdOfS);
    k.stdDevFactorB4 = 1.0 + 3.0 * relativeSdOfS;
    return k;
}

}  // namespace tt::core
