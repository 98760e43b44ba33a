#pragma once

#include <vector>

#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/lathe_pass.h"

namespace tt::core {

/// The scheduled pass machined on the simulator (paper 004's claim checked: the deformation stays
/// near Yc along the pass), next to constant fmax and constant fmin over the same length.
struct FeedScheduleCheck {
    double maxDeviationPct = 0.0;      ///< largest |Y - Yc| / Yc along the scheduled pass, percent
    double worstZMm = 0.0;             ///< where it occurs, mm
    double worstYUm = 0.0;             ///< the simulated Y there, µm
    double feedMaxExcessPct = 0.0;     ///< largest (Y - Yc) / Yc with constant fmax, percent (> 0: above Yc)
    double feedMaxWorstZMm = 0.0;      ///< where it occurs, mm
    double feedMinShortfallPct = 0.0;  ///< largest (Yc - Y) / Yc with constant fmin, percent
    std::vector<double> zMm;           ///< the positions checked, in the order of travel
    std::vector<double> scheduleUm;    ///< simulated Y with the schedule, µm
    std::vector<double> feedMaxUm;     ///< simulated Y with constant fmax, µm
    std::vector<double> feedMinUm;     ///< simulated Y with constant fmin, µm
};

/// Machines the schedule on `pass` (its depth must be the request's): Y at every node of the shaft
/// model inside the pass, at both ends, and just before and after each feed change (both feeds at the
/// breakpoint). Throws std::invalid_argument when the schedule is empty, the depths differ by more than
/// 1e-9 mm, or the pass leaves the shaft.
FeedScheduleCheck checkFeedSchedule(const LathePass& pass, const FeedSchedule& schedule,
                                    const FeedScheduleRequest& request);

}  // namespace tt::core
