#pragma once

#include <array>
#include <vector>

#include "core/control/feed_scheduler.h"
#include "core/model/deformation_model.h"

namespace tt::core {

/// The band a scheduled pass is judged by on the simulator: |Y - Yc| / Yc within this, percent.
inline constexpr double kFeedScheduleTolerancePct = 10.0;

/// How a targeted experiment for a feed schedule is planned and how far it may go.
struct FeedRefinementOptions {
    int maxRounds = 3;         ///< experiment, refit, reschedule, verify: at most this many times (1 .. 10)
    int maxBarsPerRound = 6;   ///< bars machined in one round at most (1 .. 20)
    int gaugesPerBar = 33;     ///< gauge points per bar (4 .. 200), chosen from the candidate positions
    double gaugeStepMm = 5.0;  ///< candidate gauge positions along the pass every this, mm (0.5 .. 100)
    int minFeedLevels = 5;     ///< the local model (cubic in f) needs this many different feeds (5 .. 20)

    /// Throws std::invalid_argument naming the option, its value and its limits.
    void validate() const;
};

/// One bar of a targeted experiment: turned at the pass's depth with one feed along its length, gauged
/// at the positions z.
struct RefinementBar {
    double feedMmPerRev = 0.0;
    std::vector<double> zMm;  ///< ascending
};

/// The targeted experiment planned for one round (sequential I-optimal design in the local model's
/// design space): the bars, and the precision along the pass that the plan expects.
struct RefinementProposal {
    double depthMm = 0.0;
    std::array<FactorCoding, 3>
        region;  ///< the local model's validity: a held at the depth, [fmin, fmax], the pass's z
    std::vector<RefinementBar> bars;
    double sigmaUm = 0.0;            ///< the scatter of one measurement the plan assumes, µm
    double marginUm = 0.0;           ///< Yc * (10 % - the schedule's own deviation), at least 1 % of Yc, µm
    double targetHalfWidthUm = 0.0;  ///< the plan aims at a 95 % band of the fitted mean of half the margin, µm
    double halfWidthBeforeUm = 0.0;  ///< largest 95 % half width of the mean along the pass before the bars, µm
    double halfWidthAfterUm = 0.0;   ///< the same expected with the bars, µm
    int measurementsBefore = 0;      ///< measurements at this depth inside the region already
    int feedLevelsBefore = 0;        ///< different feeds among them

    /// Gauge points in all bars.
    int gaugePointCount() const;
};

/// The term set of the local model a refinement fits: Y(f, z) at one depth, cubic in f and in z.
inline constexpr DeformationTermSet kRefinementTermSet = DeformationTermSet::CubicFZ;

/// The local model's region for a request: the depth held, the feed range [fmin, fmax] and the pass's z.
std::array<FactorCoding, 3> refinementRegion(const FeedScheduleRequest& request);

/// The measurements of `samples` inside `region` (the depth within 1e-9 mm, f and z inside).
DeformationSamples samplesInRegion(const DeformationSamples& samples, const std::array<FactorCoding, 3>& region);

/// Plans the next round's bars for `schedule` (made from the request): the candidates are bars at the
/// request's depth with feeds fmin + k max(f_mm, (fmax - fmin) / 140) up to fmax, each gaugeable every
/// gaugeStepMm along the pass; the rows to predict are the pass itself (every segment's feed at its
/// ends and every 2.5 mm between). Bars are added one at a time, each the one that most reduces the
/// average prediction variance along the pass (I-optimal, PredictionVarianceDesign) with its
/// gaugesPerBar best gauge points, until the largest 95 % half width of the mean (1.96 sigma
/// sqrt(x'(X'X)^-1 x)) is at most half the margin and there are minFeedLevels different feeds, or
/// maxBarsPerRound bars. `measured` are the measurements made so far (only those in the region are
/// used), `sigmaUm` the scatter of one measurement. Throws std::invalid_argument on bad options, an
/// empty schedule or sigma not positive.
RefinementProposal proposeRefinement(const FeedSchedule& schedule, const FeedScheduleRequest& request,
                                     const DeformationSamples& measured, double sigmaUm,
                                     const FeedRefinementOptions& options);

}  // namespace tt::core
