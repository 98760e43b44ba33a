#include "core/quality/normality.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/quality/distributions.h"
#include "core/quality/series.h"

namespace tt::core {

namespace {

constexpr const char* kTestName = "the Anderson-Darling normality test";
constexpr double kLargestAdjustedA2 = 13.0;
/// From this many values the Anderson-Darling sum is computed in two halves on two threads.
constexpr std::size_t kParallelNormalityValues = 100000;

/// ln Phi(z), remembering the last argument and result (a sorted series repeats its values).
class LastLogCdf {
public:
    double of(double z) {
        if (!m_valid || z != m_z) {
            m_z = z;
            m_value = logNormalCdf(z);
            m_valid = true;
        }
        return m_value;
    }

private:
    bool m_valid = false;
    double m_z = 0.0;
    double m_value = 0.0;
};

}  // namespace

double andersonDarlingPValue(double adjustedA2) {
    if (!(adjustedA2 >= 0.0) || !std::isfinite(adjustedA2))
        throw std::invalid_argument("the Anderson-Darling statistic must be a finite number >= 0 (got " +
                                    std::to_string(adjustedA2) + ")");
    const double a = adjustedA2;
    double p = 0.0;
    if (a < 0.2)
        p = 1.0 - std::exp(-13.436 + 101.14 * a - 223.73 * a * a);
    else if (a < 0.34)
        p = 1.0 - std::exp(-8.318 + 42.796 * a - 59.938 * a * a);
    else if (a < 0.6)
        p = std::exp(0.9177 - 4.279 * a - 1.38 * a * a);
    else if (a <= kLargestAdjustedA2)
        p = std::exp(1.2937 - 5.709 * a + 0.0186 * a * a);
    return std::clamp(p, 0.0, 1.0);
}

NormalityTest andersonDarlingNormalitySorted(std::span<const double> sortedValuesMm) {
    checkValues(sortedValuesMm, kMinNormalityValues, kTestName);
    const MeanAndDeviation moments = meanAndDeviation(sortedValuesMm);
    if (!(moments.stdDev > 0.0))
        throw std::invalid_argument(std::string(kTestName) + ": all " + std::to_string(moments.count) +
                                    " values are equal, so there is no distribution to test");
    const std::size_t n = sortedValuesMm.size();
    // sum_i (2i - 1) [ln Phi(z_i) + ln Phi(-z_(n+1-i))], with 1 - Phi(z) = Phi(-z) evaluated in the tail. A gauge
    // reads in steps (a micrometre), so a sorted series holds runs of equal values: each term is computed once per
    // run (the same value gives the same term; a million readings hold a few hundred distinct values).
    const auto partialSum = [&](std::size_t from, std::size_t to) {
        LastLogCdf low, high;
        double sum = 0.0;
        for (std::size_t i = from; i < to; ++i) {
            const double zLow = (sortedValuesMm[i] - moments.mean) / moments.stdDev;
            const double zHigh = (sortedValuesMm[n - 1 - i] - moments.mean) / moments.stdDev;
            sum += static_cast<double>(2 * i + 1) * (low.of(zLow) + high.of(-zHigh));
        }
        return sum;
    };
    // Over a long series the two halves of the sum run side by side (2 million ln Phi: half a second of a report).
    double sum = 0.0;
    if (n >= kParallelNormalityValues) {
        std::future<double> upper = std::async(std::launch::async, partialSum, n / 2, n);
        sum = partialSum(0, n / 2);
        sum += upper.get();
    } else {
        sum = partialSum(0, n);
    }
    const double count = static_cast<double>(n);
    NormalityTest test;
    test.count = n;
    test.a2 = std::max(0.0, -count - sum / count);
    test.a2Adjusted = test.a2 * (1.0 + 0.75 / count + 2.25 / (count * count));
    test.pValue = andersonDarlingPValue(test.a2Adjusted);
    return test;
}

NormalityTest andersonDarlingNormality(std::span<const double> valuesMm) {
    checkValues(valuesMm, kMinNormalityValues, kTestName);
    std::vector<double> sorted(valuesMm.begin(), valuesMm.end());
    std::sort(sorted.begin(), sorted.end());
    return andersonDarlingNormalitySorted(sorted);
}

}  // namespace tt::core
