#include "devices/linuxcnc/executed_path.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/control/profile_interpolation.h"

namespace tt::devices::linuxcnc {

namespace {

std::string fixed(double value, int decimals) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(decimals) << value;
    return out.str();
}

/// Where the samples of the cut reach, for the message of a part whose path was not seen.
std::string seenFrom(const std::vector<std::pair<double, double>>& cut) {
    if (cut.empty()) return " (no position on the part was read)";
    return " (positions read from z = " + fixed(cut.front().first, 1) + " to " + fixed(cut.back().first, 1) + " mm)";
}

/// The commanded path at z, radial mm: the program's straight moves between the grid's points, its first X before
/// the part and its last X after it.
double commandedAt(const core::CorrectionPath& grid, double z) {
    const std::vector<double>& zs = grid.zMm;
    if (z <= zs.front()) return grid.xCorrectionMm.front();
    if (z >= zs.back()) return grid.xCorrectionMm.back();
    const auto k = static_cast<std::size_t>(std::upper_bound(zs.begin(), zs.end(), z) - zs.begin());
    const double t = (z - zs[k - 1]) / (zs[k] - zs[k - 1]);
    return grid.xCorrectionMm[k - 1] + t * (grid.xCorrectionMm[k] - grid.xCorrectionMm[k - 1]);
}

}  // namespace

std::vector<std::pair<double, double>> cutSamples(const std::vector<std::array<double, 2>>& samplesMm,
                                                  const core::CorrectionPath& grid, const CutGeometry& geometry) {
    const double length = geometry.partLengthMm;
    const double nominalR = 0.5 * geometry.nominalDiameterMm;
    double band = geometry.largestTotalMm + 0.5 * geometry.clearanceMm;
    for (const double x : grid.xCorrectionMm)
        band = std::max(band, std::fabs(x) + 0.5 * geometry.clearanceMm);
    // In time order: the feed onto the part (at the path's first X, from the clearance before z = 0) and the cut to
    // the part's end; what comes after it (the retract) is not the cut.
    const double feedStart = -geometry.clearanceMm + 1e-3;
    std::vector<std::pair<double, double>> cut;
    for (std::size_t i = 0; i < samplesMm.size(); ++i) {
        const auto& [x, zProgram] = samplesMm[i];
        const double z = (zProgram - geometry.zOriginMm) / geometry.zDirection;
        if (z < feedStart || std::fabs(x - nominalR) > band) continue;
        if (z < length - 1e-6) {
            cut.emplace_back(z, x - nominalR);
            continue;
        }
        // The program dwells at the end of the cut, then retracts in X: the end is where the tool stood still (read
        // twice in a row); a position at the end read once is the tool still arriving, or already retracting.
        if (i + 1 < samplesMm.size() && samplesMm[i + 1] == samplesMm[i]) {
            cut.emplace_back(length, x - nominalR);
            break;
        }
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
              cut.end());
    return cut;
}

double drawnPathErrorMm(const std::vector<double>& sampleZ, const core::CorrectionPath& grid) {
    std::vector<double> commanded;
    for (const double z : sampleZ)
        commanded.push_back(commandedAt(grid, z));
    const core::PiecewiseCubic drawn = core::PiecewiseCubic::pchip(sampleZ, commanded);
    double worst = 0.0;
    for (std::size_t i = 0; i < grid.zMm.size(); ++i)
        worst = std::max(worst, std::fabs(drawn.value(grid.zMm[i]) - grid.xCorrectionMm[i]));
    return worst;
}

DrawnPath drawExecutedPath(const std::vector<std::array<double, 2>>& samplesMm, const core::CorrectionPath& grid,
                           const CutGeometry& geometry) {
    const std::vector<std::pair<double, double>> cut = cutSamples(samplesMm, grid, geometry);
    if (cut.size() < 2 || cut.front().first > 0.0) return {{}, "its start was not seen" + seenFrom(cut)};
    if (cut.back().first < geometry.partLengthMm - 1e-6) return {{}, "its end was not seen" + seenFrom(cut)};
    std::vector<double> zs, xs;
    for (const auto& [z, x] : cut) {
        zs.push_back(z);
        xs.push_back(x);
    }
    // Between the samples the path is drawn by PCHIP: where the samples are dense (0.25 mm at 15 m/min) it is the
    // executed path; where the sampling paused (a busy computer) it holds only if the commanded path, sampled alike,
    // is drawn back within kDrawnPathToleranceMm.
    const double error = drawnPathErrorMm(zs, grid);
    if (error > kDrawnPathToleranceMm)
        return {{},
                "its position was not read often enough where the path bends (drawn through the samples it could be " +
                    fixed(error * 1000.0, 2) + " um off)",
                error};
    const core::PiecewiseCubic executed = core::PiecewiseCubic::pchip(zs, xs);
    DrawnPath drawn;
    drawn.errorMm = error;
    drawn.path.zMm = grid.zMm;
    for (const double z : grid.zMm)
        drawn.path.xCorrectionMm.push_back(executed.value(z));
    return drawn;
}

namespace {
constexpr int kFeedRisePct = 5;
}  // namespace

int nextFeedOverridePct(int currentPct, const DrawnPath& last) {
    if (!last.unseen.empty() || last.errorMm > 0.5 * kDrawnPathToleranceMm)
        return std::max(kSlowestFeedPct, currentPct / 2);
    if (last.errorMm < 0.1 * kDrawnPathToleranceMm) return std::min(100, currentPct + kFeedRisePct);
    return currentPct;
}

}  // namespace tt::devices::linuxcnc
