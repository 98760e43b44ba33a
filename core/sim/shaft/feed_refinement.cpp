#include "core/sim/shaft/feed_refinement.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/sim/shaft/deformation_experiment.h"
#include "core/sim/shaft/lathe_pass.h"

namespace tt::core {

namespace {

/// Bars of round r are numbered from r times this (the grid experiment has at most 2500).
constexpr std::int64_t kBarNumbersPerRound = 10000;

std::string percent(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", v);
    return text;
}

DeformationSamples joined(const DeformationSamples& a, const DeformationSamples& b) {
    DeformationSamples out;
    const Eigen::Index n = a.size() + b.size();
    out.depthMm.resize(n);
    out.feedMmPerRev.resize(n);
    out.zMm.resize(n);
    out.deformationUm.resize(n);
    out.depthMm << a.depthMm, b.depthMm;
    out.feedMmPerRev << a.feedMmPerRev, b.feedMmPerRev;
    out.zMm << a.zMm, b.zMm;
    out.deformationUm << a.deformationUm, b.deformationUm;
    return out;
}

/// Refits, reschedules and machines the pass after a round's bars; a failure is the round's problem.
void refitAndCheck(FeedRefinementRound& round, const DeformationSamples& data, const LathePass& pass,
                   const FeedScheduleRequest& request) {
    round.measurements = static_cast<int>(data.size());
    try {
        round.fit = fitDeformationModel(data, kRefinementTermSet, false, refinementRegion(request));
        round.schedule = scheduleFeed(round.fit->model, request);
        round.check = checkFeedSchedule(pass, *round.schedule, request);
    } catch (const std::invalid_argument& e) {
        round.problem = e.what();
    }
}

}  // namespace

bool FeedRefinementRound::withinTolerance() const {
    return check && check->maxDeviationPct <= kFeedScheduleTolerancePct;
}

int FeedRefinement::barCount() const {
    int n = 0;
    for (const FeedRefinementRound& r : rounds)
        n += static_cast<int>(r.plan.bars.size());
    return n;
}

int FeedRefinement::gaugePointCount() const {
    int n = 0;
    for (const FeedRefinementRound& r : rounds)
        n += r.plan.gaugePointCount();
    return n;
}

const FeedRefinementRound* FeedRefinement::lastScheduled() const {
    for (auto r = rounds.rbegin(); r != rounds.rend(); ++r)
        if (r->schedule && r->check) return &*r;
    return nullptr;
}

bool FeedRefinement::withinTolerance() const {
    const FeedRefinementRound* last = lastScheduled();
    return last ? last->withinTolerance() : initialCheck.maxDeviationPct <= kFeedScheduleTolerancePct;
}

std::string feedStepAdvice(const FeedSchedule& schedule, const FeedScheduleRequest& request) {
    const double share = schedule.modelDeviationPct();
    if (share < kFeedScheduleTolerancePct) return {};
    std::string advice = "the feed step alone leaves " + percent(share) + " of Yc on the model itself";
    if (request.switchRule == FeedSwitchRule::AtLevel)
        advice += "; the centred switch rule halves that share";
    else
        advice += "; a finer feed step or a higher level reduces it";
    return advice;
}

FeedRefinement refineFeedSchedule(const LatheSetup& lathe, const DeformationModel& model, double sigmaUm,
                                  const DeformationSamples& measured, const FeedScheduleRequest& request,
                                  const FeedRefinementOptions& options, std::uint64_t seed,
                                  const FeedRefinementProgress& progress) {
    options.validate();
    const LathePass pass(lathe, request.depthMm);
    FeedRefinement out;
    out.initialSchedule = scheduleFeed(model, request);
    out.initialCheck = checkFeedSchedule(pass, out.initialSchedule, request);
    DeformationSamples data = samplesInRegion(measured, refinementRegion(request));
    FeedSchedule pathOfPass = out.initialSchedule;  // the pass the next round's bars are planned for
    double sigma = sigmaUm;
    bool within = out.initialCheck.maxDeviationPct <= kFeedScheduleTolerancePct;
    for (int r = 1; r <= options.maxRounds && !within; ++r) {
        FeedRefinementRound round;
        round.round = r;
        round.plan = proposeRefinement(pathOfPass, request, data, sigma, options);
        const auto report = [&](std::size_t done, std::size_t bars) { return !progress || progress(r, done, bars); };
        data = joined(data,
                      runTargetedBars(lathe, request.depthMm, round.plan.bars, seed, kBarNumbersPerRound * r, report));
        refitAndCheck(round, data, pass, request);
        if (round.fit) sigma = round.fit->regression.residualSigma;
        if (round.schedule) pathOfPass = *round.schedule;
        within = round.withinTolerance();
        out.rounds.push_back(std::move(round));
    }
    const FeedRefinementRound* last = out.lastScheduled();
    out.advice = feedStepAdvice(last ? *last->schedule : out.initialSchedule, request);
    return out;
}

}  // namespace tt::core
