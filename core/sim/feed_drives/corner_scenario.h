#pragma once

#include <string>
#include <vector>

#include "core/control/corner_drift_monitor.h"
#include "core/control/corrective_net_training.h"
#include "core/sim/feed_drives/drive_identification.h"
#include "core/sim/feed_drives/pulse_amplitude_search.h"

namespace tt::core {

/// Range of motor speeds the moves of a scenario are drawn from, rad/s (within 0.5 .. 9).
struct SpeedRange {
    double minRadPerS = kMinCornerSpeedRadPerS;
    double maxRadPerS = kMaxCornerSpeedRadPerS;
};

/// What varies from corner to corner on the machine (not in the controller's model): the friction of
/// both drives scatters, and now and then a corner is hit by a load (a hard spot, a chip) and becomes
/// a miss the drift monitor must ignore.
struct MachineVariation {
    double frictionScatter = 0.05;     ///< relative standard deviation of each drive's friction per corner
    double outlierProbability = 0.05;  ///< share of corners hit by a load
    double outlierTorqueNm = 4.0;      ///< the load on the Z motor, N·m
    double outlierDurationS = 0.03;    ///< how long it acts, s
    unsigned long long seed = 7;       ///< of the variation (the moves have their own seed)
};

/// How the network is trained on the simulator.
struct CornerTrainingSettings {
    int moves = 200;              ///< training moves (targets by the amplitude search)
    unsigned long long seed = 1;  ///< of the training moves
    PulseSearchSettings search;   ///< the bracketed amplitude search
    NetTrainingSettings network;  ///< Adam, early stopping, hidden neurons
};

/// Retraining on drift (paper 002): the monitor, how the drives are re-identified, the weight of the
/// earlier training moves and how many held-out moves a candidate network is judged on.
struct CornerRetrainSettings {
    DriftMonitorSettings monitor;
    double oldSetWeight = 0.3;                   ///< weight of each earlier training move against a recent corner's 1
    DriveIdentificationSettings identification;  ///< brackets of the drives' factors
    int validationMoves = 40;                    ///< held-out moves a candidate network must do better on
};

/// A corrective-pulse scenario (resources/presets/1v340-feed-drives.json): the drives, the cost, the
/// pulse, the speed ranges of the moves, training, retraining and the machine's own variation.
struct CornerScenario {
    std::string name;
    std::string description;
    FeedDrivesConfig drives;
    CornerCostSettings cost;
    PulseSettings pulse;
    SpeedRange xSpeeds;
    SpeedRange zSpeeds;
    CornerTrainingSettings training;
    CornerRetrainSettings retraining;
    MachineVariation machine;
    int evaluationMoves = 100;  ///< moves of a work run unless told otherwise
};

/// Throws std::invalid_argument naming the first value out of range.
void validateCornerScenario(const CornerScenario& scenario);

/// `count` moves with speeds drawn uniformly from the ranges by a generator seeded with `seed` (the
/// same moves on every platform). Throws std::invalid_argument for count outside 1 .. 100 000.
std::vector<CornerMove> drawCornerMoves(const SpeedRange& x, const SpeedRange& z, int count, unsigned long long seed);

}  // namespace tt::core
