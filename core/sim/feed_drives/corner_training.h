#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/control/corrective_net.h"
#include "core/sim/feed_drives/corner_scenario.h"

namespace tt::core {

/// A training move and the best pulse found for it on the simulator.
struct CornerExample {
    CornerMove move;
    PulseOptimum optimum;
};

/// Progress of long corner work: the stage ("targets", "network", "retraining"), done and total
/// units (moves or epochs). Returning false cancels (OperationCancelled).
using CornerProgress = std::function<bool(const std::string& stage, int done, int total)>;

/// The network's inputs for a move: (Vx1, Vz1, Vx2, Vz2), rad/s.
NetInputs netInputs(const CornerMove& move);

/// The best amplitude of every move on `drives` (findBestPulse), in order.
std::vector<CornerExample> findPulseTargets(const FeedDrivesConfig& drives, const CornerCostSettings& cost,
                                            const PulseSettings& pulse, const PulseSearchSettings& search,
                                            const std::vector<CornerMove>& moves, const CornerProgress& progress = {});

/// The examples as network samples, each with `weight`.
std::vector<NetSample> toNetSamples(const std::vector<CornerExample>& examples, double weight = 1.0);

/// A network trained on the scenario's simulator and the set it was trained on.
struct CornerNetTraining {
    CorrectiveNet net;
    std::vector<CornerExample> examples;
};

/// Draws `moves` training moves with `seed` from the scenario's speed ranges, finds the best pulse of
/// each on the simulator and trains the network on them (paper 002's training on simulated moves).
CornerNetTraining trainCornerNet(const CornerScenario& scenario, int moves, unsigned long long seed,
                                 const CornerProgress& progress = {});

/// The pulse applied for `move`: the network's amplitude within ±limit.
double pulseAmplitudeV(const CorrectiveNet& net, const PulseSettings& pulse, const CornerMove& move);

/// The amplitude search on one axis over a set of moves, to compare X and Z (paper 002: "the same
/// reduction needs a smaller corrective signal on X than on Z").
struct AxisPulseSummary {
    FeedAxis axis = FeedAxis::X;
    double meanAbsAmplitudeV = 0.0;  ///< mean |best amplitude|
    double meanWithoutMm = 0.0;      ///< mean trajectory error without a pulse
    double meanWithMm = 0.0;         ///< with the best pulse on this axis
    double reductionPct = 0.0;
};

/// Summarises examples found on one axis.
AxisPulseSummary summarisePulses(FeedAxis axis, const std::vector<CornerExample>& examples);

}  // namespace tt::core
