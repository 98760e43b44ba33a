#pragma once

#include <string>
#include <vector>

#include "core/sim/feed_drives/corner_training.h"
#include "core/sim/feed_drives/friction_identification.h"

namespace tt::core {

/// The controller records a corner's encoder positions every this many simulation steps (1 ms at
/// 0.1 ms): what the friction identification compares.
inline constexpr int kCornerRecordEvery = 10;

/// A retraining on drift.
struct CornerRetrainEvent {
    int move = 0;               ///< index of the corner after which it happened (0-based)
    std::string reason;         ///< what called for it and what was identified
    FrictionEstimate friction;  ///< the model's friction factors found from the corners
    int corners = 0;            ///< recorded corners it used
};

/// Retraining of paper 002 on recorded corners: the friction of both drives of the controller's `model`
/// is re-identified from the corners' encoder records (identifyFriction) and applied to `model`; the
/// best amplitude of each corner is found on the updated model; `net` is retrained on those corners
/// (weight 1) plus `oldSet` at the scenario's oldSetWeight, and the corners join `oldSet`. `why` starts
/// the event's reason. Throws std::invalid_argument without corners, OperationCancelled when `progress`
/// says so (then `model`, `net` and `oldSet` may hold the identified friction but the old network).
CornerRetrainEvent retrainOnCorners(const CornerScenario& scenario, FeedDrivesConfig& model, CorrectiveNet& net,
                                    std::vector<NetSample>& oldSet, const std::vector<RecordedCorner>& corners,
                                    int move, const std::string& why, const CornerProgress& progress = {});

}  // namespace tt::core
