#pragma once

#include <string>
#include <vector>

#include "core/sim/feed_drives/corner_training.h"
#include "core/sim/feed_drives/drive_identification.h"

namespace tt::core {

/// The controller records a corner's encoder positions every this many simulation steps (1 ms at
/// 0.1 ms): what the drive identification compares.
inline constexpr int kCornerRecordEvery = 10;

/// How a candidate network did against the network in use on held-out moves, on the controller's model.
struct CandidateVerdict {
    bool accepted = false;               ///< better validation and every pulse within the drive's limits
    std::string failure;                 ///< why not (empty when accepted)
    double keptCostMm = 0.0;             ///< mean cost U the model predicts with the network in use, mm
    double candidateCostMm = 0.0;        ///< the same with the candidate, mm
    double candidatePeakCurrentA = 0.0;  ///< largest current of the pulsed drive during a candidate pulse, A
};

/// Judges `candidate` against `kept` on `moves` simulated on `model`: accepted only when its mean cost U
/// is lower and each of its pulses leaves the pulsed drive below its current limit (paper 002: a large
/// amplitude "disturbs the drive and causes shock currents") and lets the tool pass the interval (no
/// stall). A corner the network in use cannot run counts against it, one the candidate cannot run
/// rejects the candidate.
CandidateVerdict judgeCandidate(const FeedDrivesConfig& model, const CornerCostSettings& cost,
                                const PulseSettings& pulse, const CorrectiveNet& kept, const CorrectiveNet& candidate,
                                const std::vector<CornerMove>& moves);

/// A retraining on drift, done or refused.
struct CornerRetrainEvent {
    int move = 0;               ///< index of the corner after which it happened (0-based)
    std::string reason;         ///< what called for it, what was identified and what became of the candidate
    int corners = 0;            ///< recorded corners it used
    DriveEstimate identified;   ///< the drives' factors found from the corners
    bool modelUpdated = false;  ///< they reproduce the records better than the model's and replaced them
    CandidateVerdict verdict;   ///< the candidate network against the one in use; accepted: it replaced it
    int retargetedMoves = 0;    ///< earlier training moves whose best pulse was found again on the model
};

/// Retraining of paper 002 on recorded corners, guarded. (1) The drives' factors are re-identified
/// from the corners' encoder records (identifyDrives on `nominal`, from the factors of `model`); they
/// replace `model` when they reproduce the records better. (2) The best amplitude of each recorded
/// corner and of each earlier training move of `trainingSet` is found on that model (the earlier
/// targets belonged to the machine before the drift). (3) A candidate is retrained from `net` on them
/// (the corners weigh 1, the earlier moves the scenario's oldSetWeight). (4) It replaces `net` only when
/// judgeCandidate accepts it on the scenario's validationMoves held-out moves; then `trainingSet`
/// becomes the re-targeted set plus the corners. Otherwise, or when a step fails, `net` and
/// `trainingSet` stay as they were and the event says why. `why` starts the event's reason. Throws
/// std::invalid_argument without corners, OperationCancelled when `progress` says so (then nothing
/// is changed).
CornerRetrainEvent retrainOnCorners(const CornerScenario& scenario, FeedDrivesFactors& model, CorrectiveNet& net,
                                    std::vector<NetSample>& trainingSet, const std::vector<RecordedCorner>& corners,
                                    int move, const std::string& why, const CornerProgress& progress = {});

}  // namespace tt::core
