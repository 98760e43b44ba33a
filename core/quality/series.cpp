#include "core/quality/series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

void checkValues(std::span<const double> valuesMm, std::size_t minimumCount, const std::string& purpose) {
    if (valuesMm.size() < minimumCount)
        throw std::invalid_argument(purpose + " needs at least " + std::to_string(minimumCount) + " values (got " +
                                    std::to_string(valuesMm.size()) + ")");
    if (valuesMm.size() > kMaxSeriesValues)
        throw std::invalid_argument(purpose + " takes at most " + std::to_string(kMaxSeriesValues) + " values (got " +
                                    std::to_string(valuesMm.size()) + ")");
    for (std::size_t i = 0; i < valuesMm.size(); ++i) {
        const double v = valuesMm[i];
        if (!std::isfinite(v) || std::abs(v) > kMaxAbsMeasurementMm)
            throw std::invalid_argument(purpose + ": value " + std::to_string(i + 1) + " (" + std::to_string(v) +
                                        " mm) is not a measured size within +-1e6 mm");
    }
}

void checkSeries(const MeasuredSeries& series, std::size_t minimumCount, const std::string& purpose) {
    const std::size_t n = series.valuesMm.size();
    if (series.partNumbers.size() != n || series.timesS.size() != n)
        throw std::invalid_argument(purpose + ": the series has " + std::to_string(n) + " values but " +
                                    std::to_string(series.partNumbers.size()) + " part numbers and " +
                                    std::to_string(series.timesS.size()) + " times");
    checkValues(series.valuesMm, minimumCount, purpose);
}

MeanAndDeviation meanAndDeviation(std::span<const double> values) {
    if (values.empty()) throw std::invalid_argument("a mean needs at least one value");
    MeanAndDeviation result;
    result.count = values.size();
    const double n = static_cast<double>(values.size());
    double sum = 0.0;
    for (const double v : values)
        sum += v;
    result.mean = sum / n;
    double sumOfDeviations = 0.0;
    double sumOfSquares = 0.0;
    for (const double v : values) {
        const double d = v - result.mean;
        sumOfDeviations += d;
        sumOfSquares += d * d;
    }
    if (result.count > 1)
        result.stdDev = std::sqrt(std::max(0.0, sumOfSquares - sumOfDeviations * sumOfDeviations / n) / (n - 1.0));
    return result;
}

std::vector<std::int64_t> partsOfPoints(const MeasuredSeries& series, int subgroupSize,
                                        std::span<const std::size_t> points) {
    if (subgroupSize < 1) throw std::invalid_argument("the subgroup size must be at least 1");
    const auto n = static_cast<std::size_t>(subgroupSize);
    std::vector<std::int64_t> parts;
    parts.reserve(points.size() * n);
    for (const std::size_t point : points) {
        if ((point + 1) * n > series.partNumbers.size())
            throw std::invalid_argument("chart point " + std::to_string(point + 1) + " lies beyond the " +
                                        std::to_string(series.partNumbers.size()) + " measured parts");
        for (std::size_t i = point * n; i < (point + 1) * n; ++i)
            parts.push_back(series.partNumbers[i]);
    }
    return parts;
}

}  // namespace tt::core
