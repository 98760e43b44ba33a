#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/control/feed_refinement_design.h"
#include "core/control/feed_scheduler.h"
#include "core/model/deformation_model.h"
#include "core/sim/shaft/feed_schedule_check.h"
#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// One round of closing the loop on the force-deformation model: the targeted bars planned and machined
/// on the simulator, the local model refitted on every measurement at the depth, the pass rescheduled
/// on it and machined again.
struct FeedRefinementRound {
    int round = 0;                           ///< 1, 2, ...
    RefinementProposal plan;                 ///< the bars machined and the precision the plan expected
    int measurements = 0;                    ///< measurements at the depth after the round
    std::optional<DeformationFit> fit;       ///< the local model (empty when the data cannot carry it yet)
    std::optional<FeedSchedule> schedule;    ///< the pass rescheduled on it
    std::optional<FeedScheduleCheck> check;  ///< the rescheduled pass on the simulator
    std::string problem;                     ///< why there is no fit or no schedule, in the engine's words

    /// Whether the round's pass stayed within kFeedScheduleTolerancePct of Yc on the simulator.
    bool withinTolerance() const;
};

/// The schedule before the refinement, the rounds and the result.
struct FeedRefinement {
    FeedSchedule initialSchedule;
    FeedScheduleCheck initialCheck;
    std::vector<FeedRefinementRound> rounds;
    std::string advice;  ///< when more measurements cannot help (the feed step alone leaves the band), why

    /// Bars machined in all rounds.
    int barCount() const;
    /// Gauge points measured in all rounds.
    int gaugePointCount() const;
    /// The last round with a schedule and a check, if any (the result: it rests on the most data).
    const FeedRefinementRound* lastScheduled() const;
    /// Whether the result (the last scheduled round, or the initial schedule when none) is within the band.
    bool withinTolerance() const;
};

/// Called after each bar with (round, bars done in it, bars planned in it); returning false stops.
using FeedRefinementProgress = std::function<bool(int round, std::size_t barsDone, std::size_t bars)>;

/// The advice when the model's own schedule leaves the band (the feed step's sawtooth, before any model
/// error): empty when it does not. Names the share and, under the paper's switch rule, the centred one.
std::string feedStepAdvice(const FeedSchedule& schedule, const FeedScheduleRequest& request);

/// Schedules the request on `model` and machines the pass on `lathe`; while it leaves
/// kFeedScheduleTolerancePct of Yc, up to options.maxRounds rounds of: plan the bars that most reduce the
/// prediction variance along the pass (proposeRefinement; the scatter `sigmaUm` of the model in the
/// first round, the local model's after), turn and gauge them (runTargetedBars, bars numbered from
/// 10000 * round, micrometer seed `seed`), fit the local model Y(f, z) at the depth (kRefinementTermSet,
/// no stepwise) on `measured` inside the region and every bar so far, reschedule and machine the pass.
/// A round whose model cannot be fitted or scheduled yet records why and the next round adds bars.
/// Throws std::invalid_argument on bad options or a request the model cannot schedule;
/// DeformationExperimentStopped when `progress` returns false.
FeedRefinement refineFeedSchedule(const LatheSetup& lathe, const DeformationModel& model, double sigmaUm,
                                  const DeformationSamples& measured, const FeedScheduleRequest& request,
                                  const FeedRefinementOptions& options, std::uint64_t seed,
                                  const FeedRefinementProgress& progress = {});

}  // namespace tt::core
