// The executed path drawn from sampled tool positions (devices/linuxcnc/executed_path.h): pure, no LinuxCNC. The
// samples are made here as a watcher of the tool sees them: the feed onto the part, the cut, the dwell at the end and
// the retract, in program coordinates, with the sampling paused where a busy computer would pause it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "devices/linuxcnc/executed_path.h"

namespace tt {
namespace {

using devices::linuxcnc::CutGeometry;
using devices::linuxcnc::drawExecutedPath;
using devices::linuxcnc::drawnPathErrorMm;
using devices::linuxcnc::kDrawnPathToleranceMm;
using devices::linuxcnc::kSlowestFeedPct;
using devices::linuxcnc::nextFeedOverridePct;
using Samples = std::vector<std::array<double, 2>>;

constexpr double kLength = 325.0, kDiameter = 40.0, kStep = 5.0;

CutGeometry geometry() {
    CutGeometry g;
    g.partLengthMm = kLength;
    g.nominalDiameterMm = kDiameter;
    g.zOriginMm = -2.0;  // program Z of the part's left end; the cut runs towards -Z
    g.zDirection = -1;
    g.clearanceMm = 2.0;
    g.largestTotalMm = 0.1;
    return g;
}

/// A commanded path on the 5 mm grid: straight (0.01 mm) over z 100 .. 200, a 20 um half-sine bend elsewhere.
double commanded(double z) {
    if (z >= 100.0 && z <= 200.0) return 0.01;
    const double bend = z < 100.0 ? z / 100.0 : (z - 200.0) / (kLength - 200.0);
    return 0.01 + 0.02 * std::sin(std::numbers::pi * bend);
}

core::CorrectionPath grid() {
    core::CorrectionPath path;
    for (double z = 0.0; z <= kLength + 1e-9; z += kStep) {
        path.zMm.push_back(z);
        path.xCorrectionMm.push_back(commanded(z));
    }
    return path;
}

/// The commanded path between its grid points (the program's straight moves), radial mm.
double onGrid(const core::CorrectionPath& path, double z) {
    const auto k = static_cast<std::size_t>(std::min(z / kStep, static_cast<double>(path.zMm.size() - 2)));
    const double t = (z - path.zMm[k]) / kStep;
    return path.xCorrectionMm[k] + t * (path.xCorrectionMm[k + 1] - path.xCorrectionMm[k]);
}

/// What a watcher of the tool sees every `everyMm` along the cut, except where z is in [skipFrom, skipTo): the feed
/// from the clearance, the cut, the end and the retract to a safe X, in program coordinates (radius X, Z).
Samples watch(const core::CorrectionPath& path, double everyMm, double skipFrom = 0.0, double skipTo = 0.0,
              double firstZ = -1.5) {
    const CutGeometry g = geometry();
    const double r = 0.5 * kDiameter;
    const auto program = [&](double z, double x) {
        return std::array<double, 2>{r + x, g.zOriginMm + g.zDirection * z};
    };
    Samples samples;
    for (double z = firstZ; z < kLength; z += everyMm)
        if (z < skipFrom || z >= skipTo) samples.push_back(program(z, onGrid(path, std::max(z, 0.0))));
    samples.push_back(program(kLength, path.xCorrectionMm.back()));
    samples.push_back(samples.back());                                       // the dwell: read twice in a row
    samples.push_back(program(kLength, path.xCorrectionMm.back() + 0.003));  // the retract, in X
    samples.push_back(program(kLength, g.largestTotalMm + g.clearanceMm));
    samples.push_back(program(-2.0, g.largestTotalMm + g.clearanceMm));
    return samples;
}

double largestDifference(const core::CorrectionPath& a, const core::CorrectionPath& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.zMm.size(); ++i)
        worst = std::max(worst, std::fabs(a.xCorrectionMm[i] - b.xCorrectionMm[i]));
    return worst;
}

TEST(ExecutedPath, DenseSamplesDrawTheExecutedPathOnTheGrid) {
    const core::CorrectionPath path = grid();
    // 0.25 mm: the sampling of a simulated LinuxCNC cutting at 15 m/min on an idle computer.
    const auto drawn = drawExecutedPath(watch(path, 0.25), path, geometry());
    ASSERT_TRUE(drawn.unseen.empty()) << drawn.unseen;
    ASSERT_EQ(drawn.path.zMm, path.zMm);
    EXPECT_LT(largestDifference(drawn.path, path), kDrawnPathToleranceMm);
}

TEST(ExecutedPath, APauseAlongAStraightStretchCostsNothing) {
    const core::CorrectionPath path = grid();
    // 80 mm without a sample where the path is straight (z 110 .. 190).
    const auto drawn = drawExecutedPath(watch(path, 0.25, 110.0, 190.0), path, geometry());
    ASSERT_TRUE(drawn.unseen.empty()) << drawn.unseen;
    EXPECT_LT(largestDifference(drawn.path, path), kDrawnPathToleranceMm);
}

TEST(ExecutedPath, APauseWhereThePathBendsIsRefusedSayingHowFarOffTheDrawingCouldBe) {
    const core::CorrectionPath path = grid();
    // The same 80 mm pause where the path bends (z 10 .. 90): PCHIP across it is micrometres off the bend.
    const auto drawn = drawExecutedPath(watch(path, 0.25, 10.0, 90.0), path, geometry());
    EXPECT_TRUE(drawn.path.zMm.empty());
    EXPECT_NE(drawn.unseen.find("not read often enough where the path bends"), std::string::npos) << drawn.unseen;
    EXPECT_NE(drawn.unseen.find(" um off"), std::string::npos) << drawn.unseen;
    // A short pause there (1 mm, 4 ms at 15 m/min) is drawn back within the tolerance.
    EXPECT_TRUE(drawExecutedPath(watch(path, 0.25, 40.0, 41.0), path, geometry()).unseen.empty());
}

TEST(ExecutedPath, WithoutTheStartOrTheEndOfTheCutThePathIsNotDrawn) {
    const core::CorrectionPath path = grid();
    const auto lateStart = drawExecutedPath(watch(path, 0.25, 0.0, 0.0, 12.0), path, geometry());
    EXPECT_TRUE(lateStart.path.zMm.empty());
    EXPECT_EQ(lateStart.unseen, "its start was not seen (positions read from z = 12.0 to 325.0 mm)");

    Samples noEnd = watch(path, 0.25);
    noEnd.erase(noEnd.end() - 5, noEnd.end());  // the end, its dwell and the retract
    noEnd.erase(std::remove_if(noEnd.begin(), noEnd.end(), [](const auto& s) { return s[1] < -2.0 - 300.0; }),
                noEnd.end());  // nothing read after z = 300
    const auto drawn = drawExecutedPath(noEnd, path, geometry());
    EXPECT_TRUE(drawn.path.zMm.empty());
    EXPECT_EQ(drawn.unseen.rfind("its end was not seen (positions read from z = -1.5 to 300.0 mm)", 0), 0u)
        << drawn.unseen;

    EXPECT_EQ(drawExecutedPath({}, path, geometry()).unseen,
              "its start was not seen (no position on the part was read)");

    // The dwell at the end not read (a busy computer): the first position at the end is the retract's, 3 um off the
    // part; it is not taken for the end of the cut.
    Samples dwellMissed = watch(path, 0.25);
    dwellMissed.erase(dwellMissed.end() - 5, dwellMissed.end() - 3);
    const auto missed = drawExecutedPath(dwellMissed, path, geometry());
    EXPECT_TRUE(missed.path.zMm.empty());
    EXPECT_EQ(missed.unseen.rfind("its end was not seen", 0), 0u) << missed.unseen;
}

TEST(ExecutedPath, TheCommandedPathSampledOnItsOwnGridIsDrawnBackExactly) {
    const core::CorrectionPath path = grid();
    EXPECT_LT(drawnPathErrorMm(path.zMm, path), 1e-12);
    // Every other grid point: the bends are drawn a little off, the straight stretch not at all.
    std::vector<double> sparse;
    for (std::size_t i = 0; i < path.zMm.size(); i += 2)
        sparse.push_back(path.zMm[i]);
    if (sparse.back() != kLength) sparse.push_back(kLength);
    EXPECT_GT(drawnPathErrorMm(sparse, path), 0.0);
}

TEST(ExecutedPath, TheCutSlowsWhileTheSamplingCannotKeepUpAndSpeedsUpAgainWhenItCan) {
    const core::CorrectionPath path = grid();
    // A pause where the path bends that the tolerance still accepts (more than half of it): the next cut is slower.
    const auto marginal = drawExecutedPath(watch(path, 0.25, 45.0, 53.0), path, geometry());
    ASSERT_TRUE(marginal.unseen.empty()) << marginal.unseen;
    ASSERT_GT(marginal.errorMm, 0.5 * kDrawnPathToleranceMm) << "an 8 mm pause at the bend";
    EXPECT_EQ(nextFeedOverridePct(100, marginal), 50);
    // A path not seen halves it too, never below the slowest pace.
    const auto unseen = drawExecutedPath(watch(path, 0.25, 10.0, 90.0), path, geometry());
    ASSERT_FALSE(unseen.unseen.empty());
    EXPECT_EQ(nextFeedOverridePct(50, unseen), 25);
    EXPECT_EQ(nextFeedOverridePct(kSlowestFeedPct + 1, unseen), kSlowestFeedPct);
    EXPECT_EQ(nextFeedOverridePct(kSlowestFeedPct, unseen), kSlowestFeedPct);
    // Dense samples: back up by 5 points a part, to the programmed feed and no further.
    const auto dense = drawExecutedPath(watch(path, 0.25), path, geometry());
    ASSERT_LT(dense.errorMm, 0.1 * kDrawnPathToleranceMm);
    int pct = kSlowestFeedPct;
    int parts = 0;
    for (; pct < 100 && parts < 100; ++parts)
        pct = nextFeedOverridePct(pct, dense);
    EXPECT_EQ(pct, 100);
    EXPECT_EQ(parts, (100 - kSlowestFeedPct) / 5) << "5 points a part from the slowest pace to the programmed feed";
    EXPECT_EQ(nextFeedOverridePct(100, dense), 100);
}

}  // namespace
}  // namespace tt
