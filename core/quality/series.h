#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tt::core {

/// The most values one analysis takes (a history of 10 million parts at one control point, 80 MB).
inline constexpr std::size_t kMaxSeriesValues = 10'000'000;
/// The largest magnitude a measured value may have, mm (keeps every sum of squares far from overflow).
inline constexpr double kMaxAbsMeasurementMm = 1.0e6;

/// The measured diameters of one characteristic (one control point) in production order, each with the
/// part it was measured on and when. The three vectors have the same length; the statistics use the
/// values, the part numbers and times are carried to the results (which parts a rule violation involves).
struct MeasuredSeries {
    std::vector<double> valuesMm;
    std::vector<std::int64_t> partNumbers;
    std::vector<double> timesS;  ///< seconds on the caller's clock (e.g. UNIX time); never used in a formula
};

/// Throws std::invalid_argument when the three vectors differ in length, or a value fails checkValues.
void checkSeries(const MeasuredSeries& series, std::size_t minimumCount, const std::string& purpose);

/// Throws std::invalid_argument, naming `purpose` (e.g. "the X-bar chart"), when there are fewer than
/// `minimumCount` or more than kMaxSeriesValues values, or a value is not finite or beyond
/// +-kMaxAbsMeasurementMm.
void checkValues(std::span<const double> valuesMm, std::size_t minimumCount, const std::string& purpose);

/// Mean and standard deviation of some values (the standard deviation with the n - 1 divisor, 0 for one
/// value).
struct MeanAndDeviation {
    std::size_t count = 0;
    double mean = 0.0;
    double stdDev = 0.0;
};

/// Mean and sample standard deviation (n - 1) by the corrected two-pass algorithm, sum (x - m)^2 -
/// (sum (x - m))^2 / n (Chan, Golub & LeVeque 1983, Am. Stat. 37(3), eq. 1.7). At least one value; the
/// values are not range-checked here (the callers check them).
MeanAndDeviation meanAndDeviation(std::span<const double> values);

/// The part numbers of chart points: point k of a chart of subgroups of `subgroupSize` consecutive
/// values (1 for individuals) covers values k*n .. k*n + n - 1. Throws std::invalid_argument when a point
/// lies beyond the series.
std::vector<std::int64_t> partsOfPoints(const MeasuredSeries& series, int subgroupSize,
                                        std::span<const std::size_t> points);

}  // namespace tt::core
