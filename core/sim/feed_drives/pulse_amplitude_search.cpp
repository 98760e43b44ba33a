#include "core/sim/feed_drives/pulse_amplitude_search.h"

#include "core/common/brent_minimum.h"

namespace tt::core {

PulseOptimum findBestPulse(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const CornerMove& move,
                           const PulseSettings& pulse, const PulseSearchSettings& search) {
    const auto u = [&](double amplitudeV) { return simulateCorner(drives, cost, move, pulse, amplitudeV).cost.cost; };
    const ScalarMinimum m =
        minimiseOnGrid(u, -pulse.limitV, pulse.limitV, search.gridPoints, search.toleranceV, search.maxSimulations);
    PulseOptimum best;
    best.amplitudeV = m.x;
    best.with = simulateCorner(drives, cost, move, pulse, m.x).cost;
    best.without = simulateCorner(drives, cost, move, pulse, 0.0).cost;
    best.simulations = m.evaluations + 2;
    return best;
}

}  // namespace tt::core
