#pragma once
// The path LinuxCNC executed for a part, drawn from the tool positions sampled while it cut. Pure: no LinuxCNC, no
// clock; the LinuxCNC lathe applies the built-in physics to what this draws.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/ports/correction_output.h"

namespace tt::devices::linuxcnc {

/// Where the part sits in the program's coordinates, and the band around it that is the cut, mm.
struct CutGeometry {
    double partLengthMm = 0.0;
    double nominalDiameterMm = 0.0;
    double zOriginMm = 0.0;    ///< program Z of the part's z = 0
    int zDirection = -1;       ///< +1 or -1: program Z = zOrigin + zDirection * z
    double clearanceMm = 0.0;  ///< the approach starts this far before z = 0 (and this far off the part in X)
    double largestTotalMm = 0.0;
};

/// How far the drawn path may stray from the executed one, radial mm: 0.5 um on diameter, half the 1 um the
/// corrections must land within (and well under the scatter of a turned diameter).
inline constexpr double kDrawnPathToleranceMm = 2.5e-4;

/// The drawn path on the grid, or an empty path and, in the operator's words, why the samples do not show the cut.
struct DrawnPath {
    core::CorrectionPath path;
    std::string unseen;
    double errorMm = 0.0;  ///< drawnPathErrorMm of the samples (0 when the start or the end was not seen)
};

/// The slowest pace of the cut, % of the programmed feed (LinuxCNC's feed override).
inline constexpr int kSlowestFeedPct = 10;

/// The feed override for the next part, %, from the current one and what the last part's samples showed: a path
/// not seen, or drawn with more than half the tolerance, halves it (down to kSlowestFeedPct), so that the sampler of
/// a busy computer sees the next path whole; a path drawn within a tenth of it raises it by 5 points, up to 100 %
/// (slowly: a busy computer's pauses come and go).
int nextFeedOverridePct(int currentPct, const DrawnPath& last);

/// The samples of the cut (the feed onto the part and the cut to its end, not the retract) as (z along the part,
/// radial correction), mm, sorted by z. `samplesMm` are program X (radius) and Z in time order, a position where the
/// tool stood still twice in a row (the dwell at the end of the cut: the end is seen only there).
std::vector<std::pair<double, double>> cutSamples(const std::vector<std::array<double, 2>>& samplesMm,
                                                  const core::CorrectionPath& grid, const CutGeometry& geometry);

/// How far a path drawn through samples taken at `sampleZ` can stray from the commanded `grid` path (straight moves
/// between its points) between them, radial mm: the commanded path sampled at the same places, drawn by PCHIP and
/// compared on the grid. A pause of the sampling where the path bends gives a large value; along a straight stretch
/// it costs nothing.
double drawnPathErrorMm(const std::vector<double>& sampleZ, const core::CorrectionPath& grid);

/// The executed path on the grid of the commanded `grid` path: PCHIP through the cut's samples, when they reach both
/// ends of the part and draw the commanded path back within kDrawnPathToleranceMm.
DrawnPath drawExecutedPath(const std::vector<std::array<double, 2>>& samplesMm, const core::CorrectionPath& grid,
                           const CutGeometry& geometry);

}  // namespace tt::devices::linuxcnc
