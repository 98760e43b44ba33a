#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/sim/feed_drives/corner_retraining.h"

namespace tt::core {

/// One corner of a work run.
struct CornerWorkMove {
    CornerMove move;
    double amplitudeV = 0.0;  ///< the network's pulse
    CornerCost without;       ///< measured on the machine without the pulse
    CornerCost with;          ///< measured with it
    CornerCost predicted;     ///< what the controller's model expected with it
    bool hitByLoad = false;   ///< the machine's variation made it a miss
};

/// Where, what and how much the machine drifts during a work run.
struct CornerDrift {
    DriveDriftKind kind = DriveDriftKind::Friction;  ///< what drifts
    double factor = 1.0;                             ///< multiplies it, 0.5 .. 3 (1: no drift)
    FeedAxis axis = FeedAxis::Z;                     ///< the drive that drifts
    int atMove = -1;                                 ///< first move on the drifted machine; −1: the middle of the run
};

/// Result of a work run (`trueturn corner`).
struct CornerWorkResult {
    std::vector<CornerWorkMove> moves;
    std::vector<CornerRetrainEvent> retrains;
    double meanWithoutMm = 0.0;  ///< mean trajectory error without the pulse over the moves
    double meanWithMm = 0.0;     ///< with the network's pulse
    double reductionPct = 0.0;
    std::optional<double> reductionAfterRetrainPct;  ///< over the moves after the first retraining
    int driftAtMove = -1;                            ///< where the drift began (−1: none)
    std::vector<DriftCheck> checks;                  ///< the monitor's verdict after each move
    FeedDrivesFactors model;                         ///< the controller's model at the end (identified factors)
    std::vector<NetSample> samples;                  ///< the training set at the end (old set + retrained corners)
    std::vector<RecordedCorner> recent;              ///< corners since the last retraining, misses left out
};

/// Runs `moves` on the simulated machine (the scenario's drives with its per-corner variation and the
/// drift) with the pulses of `net`. After each corner the drift monitor compares the cost the
/// controller's model predicted with the one measured; when it calls for retraining, retrainOnCorners
/// works on the recent corners (misses left out): the drives are re-identified, the best amplitudes
/// found on the model, and a retrained network replaces `net` only when it does better on held-out
/// moves within the drive's limits (a refused retraining is an event too). The monitor starts a new
/// window after each. When `retrain` is false the monitor only watches. `net` is updated in place.
/// Throws std::invalid_argument when the drift is outside 0.5 .. 3 or makes a drive unable to move.
CornerWorkResult runCornerWork(const CornerScenario& scenario, CorrectiveNet& net, std::vector<NetSample> oldSet,
                               const std::vector<CornerMove>& moves, const CornerDrift& drift, bool retrain = true,
                               const CornerProgress& progress = {});

/// The machine of corner `index`: `base` with the friction scatter of `variation` (each drive's factor
/// within 1 ± 4 standard deviations, at least 0.5), and the load of a miss when the corner is one.
struct CornerMachine {
    FeedDrivesConfig drives;
    std::optional<LoadTorquePulse> load;
};
CornerMachine machineForCorner(const FeedDrivesConfig& base, const MachineVariation& variation, int index);

}  // namespace tt::core
