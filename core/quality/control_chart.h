#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace tt::core {

/// The Shewhart chart pairs of core/quality.
enum class ChartKind {
    XbarRange,               ///< subgroup means and ranges (X-bar-R)
    XbarStdDev,              ///< subgroup means and standard deviations (X-bar-s)
    IndividualsMovingRange,  ///< individual values and moving ranges of two (I-MR)
};

/// Lower limit, centre line and upper limit of one chart, in the units of the plotted statistic (mm).
struct ControlLimits {
    double lowerMm = 0.0;
    double centreMm = 0.0;
    double upperMm = 0.0;
};

/// Which chart points (subgroups, or individual values for I-MR) form the phase-I baseline the limits are
/// computed from; the limits are then held for every point (phase II). pointCount 0 = to the last point.
struct ChartBaseline {
    std::size_t firstPoint = 0;
    std::size_t pointCount = 0;
};

/// The limits of a chart pair computed from a baseline (phase I), to be held for later data (phase II).
struct ChartLimits {
    ChartKind kind = ChartKind::XbarRange;
    int subgroupSize = 1;        ///< n (1 for I-MR)
    ControlLimits location;      ///< X-bar or individuals chart
    ControlLimits spread;        ///< R, s or moving-range chart
    double sigmaWithinMm = 0.0;  ///< R-bar/d2, s-bar/c4 or MR-bar/d2(2), mm
    double locationSigmaMm =
        0.0;  ///< sigma of the plotted location statistic, sigmaWithin/sqrt(n): zones of the run rules
    std::size_t baselineFirstPoint = 0;
    std::size_t baselinePointCount = 0;
};

/// A chart pair over a whole series, every point against the held limits.
struct ControlChart {
    ChartLimits limits;
    std::vector<double> locationMm;  ///< one per point: subgroup means, or the individual values
    /// Spread per point: subgroup ranges or standard deviations (spreadMm[k] belongs to point k), or moving
    /// ranges |x[k+1] - x[k]| (spreadMm[k] belongs to point k + 1: spreadFirstPoint = 1).
    std::vector<double> spreadMm;
    std::size_t spreadFirstPoint = 0;
    std::vector<std::size_t> locationBeyondLimits;  ///< points strictly outside the location limits
    std::vector<std::size_t> spreadBeyondLimits;    ///< points (numbered as the location's) outside the spread limits
    std::size_t unusedValues = 0;                   ///< values after the last complete subgroup, left out
};

/// The baseline as a checked [first, first + count) range of `pointCount` chart points: throws
/// std::invalid_argument, naming `chartName`, when it starts beyond the points, reaches past them, or holds
/// fewer than `minimumPoints`.
ChartBaseline resolveBaseline(const ChartBaseline& baseline, std::size_t pointCount, std::size_t minimumPoints,
                              const std::string& chartName);

/// Checks limits held from an earlier study (e.g. read back from storage): every figure finite, lower <=
/// centre <= upper on both charts, both sigmas above 0, subgroup size 1 for I-MR and 2..25 for X-bar.
/// Throws std::invalid_argument naming the problem.
void checkHeldLimits(const ChartLimits& limits);

/// Indices of the values strictly below limits.lowerMm or above limits.upperMm; `indexOffset` is added to
/// each index (1 for moving ranges).
std::vector<std::size_t> pointsBeyondLimits(std::span<const double> valuesMm, const ControlLimits& limits,
                                            std::size_t indexOffset = 0);

}  // namespace tt::core
