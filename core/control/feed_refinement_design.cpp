#include "core/control/feed_refinement_design.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/model/optimal_design.h"

namespace tt::core {

namespace {

/// Spacing of the prediction rows along each segment of the pass, mm.
constexpr double kPassStepMm = 2.5;
/// The plan's 95 % quantile (normal: the plan is made before the fit's degrees of freedom are known).
constexpr double kPlanQuantile = 1.96;
/// The candidate feeds are at most this many (the machine's increment, or coarser).
constexpr double kMaxCandidateSteps = 140.0;
/// The margin the plan aims at is never taken below this share of Yc, percent.
constexpr double kSmallestMarginPct = 1.0;
/// Two depths within this are the same, mm.
constexpr double kSameDepthMm = 1e-9;

std::string num(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

void requireRange(int value, int lo, int hi, const char* what) {
    if (value < lo || value > hi)
        throw std::invalid_argument(std::string(what) + " " + std::to_string(value) + " is outside " +
                                    std::to_string(lo) + " .. " + std::to_string(hi));
}

/// The rows of the local model's terms at the points (f, z) of one depth.
Eigen::MatrixXd rowsAt(const DeformationModel& shape, double depthMm, const std::vector<double>& feeds,
                       const std::vector<double>& zs) {
    Eigen::MatrixXd rows(static_cast<Eigen::Index>(zs.size()), static_cast<Eigen::Index>(shape.terms().size()));
    for (std::size_t i = 0; i < zs.size(); ++i)
        rows.row(static_cast<Eigen::Index>(i)) = shape.termRow(depthMm, feeds[i], zs[i]).transpose();
    return rows;
}

/// The pass as rows to predict at: each segment's feed at its ends and every kPassStepMm between.
Eigen::MatrixXd passRows(const DeformationModel& shape, const FeedSchedule& schedule, double depthMm) {
    std::vector<double> feeds;
    std::vector<double> zs;
    for (const FeedSegment& s : schedule.segments) {
        const int steps = std::max(1, static_cast<int>(std::ceil(s.lengthMm() / kPassStepMm)));
        for (int k = 0; k <= steps; ++k) {
            feeds.push_back(s.feedMmPerRev);
            zs.push_back(s.zFromMm + (s.zToMm - s.zFromMm) * k / steps);
        }
    }
    return rowsAt(shape, depthMm, feeds, zs);
}

std::vector<double> candidateFeeds(const FeedScheduleRequest& r) {
    const double span = r.feedMaxMmPerRev - r.feedMinMmPerRev;
    const double step = std::max(r.feedStepMmPerRev, span / kMaxCandidateSteps);
    std::vector<double> feeds;
    // Rounded to 1e-6 mm/rev (the F word's resolution is 1e-4): 0.105, not 0.10500000000000001.
    for (int k = 0; r.feedMinMmPerRev + k * step < r.feedMaxMmPerRev - 1e-9 * span; ++k)
        feeds.push_back(std::round((r.feedMinMmPerRev + k * step) * 1e6) / 1e6);
    feeds.push_back(r.feedMaxMmPerRev);
    return feeds;
}

std::vector<double> candidateGauges(const FactorCoding& z, double stepMm) {
    std::vector<double> zs;
    const int steps = std::max(1, static_cast<int>(std::round((z.max - z.min) / stepMm)));
    for (int k = 0; k <= steps; ++k)
        zs.push_back(z.min + (z.max - z.min) * k / steps);
    return zs;
}

/// One bar of the round: the candidate feed whose gauge points most reduce the average variance (a
/// feed of `measuredFeeds` only when `newFeedOnly` is false).
RefinementBar bestBar(const PredictionVarianceDesign& design, const DeformationModel& shape, double depthMm,
                      const std::vector<double>& feeds, const std::vector<double>& gauges, int gaugesPerBar,
                      const std::set<double>& measuredFeeds, bool newFeedOnly) {
    double bestReduction = -1.0;
    double bestFeed = feeds.front();
    for (double f : feeds) {
        if (newFeedOnly && measuredFeeds.count(f) > 0) continue;
        const double reduction =
            design.reductionOf(rowsAt(shape, depthMm, std::vector<double>(gauges.size(), f), gauges));
        if (reduction > bestReduction) {
            bestReduction = reduction;
            bestFeed = f;
        }
    }
    const Eigen::MatrixXd rows = rowsAt(shape, depthMm, std::vector<double>(gauges.size(), bestFeed), gauges);
    RefinementBar bar{bestFeed, {}};
    for (Eigen::Index i : design.chooseRows(rows, gaugesPerBar))
        bar.zMm.push_back(gauges[static_cast<std::size_t>(i)]);
    return bar;
}

}  // namespace

void FeedRefinementOptions::validate() const {
    requireRange(maxRounds, 1, 10, "the number of refinement rounds");
    requireRange(maxBarsPerRound, 1, 20, "the bars per refinement round");
    requireRange(gaugesPerBar, 4, 200, "the gauge points per bar");
    requireRange(minFeedLevels, 5, 20, "the feed levels of the local model");
    if (!std::isfinite(gaugeStepMm) || gaugeStepMm < 0.5 || gaugeStepMm > 100.0)
        throw std::invalid_argument("the gauge step " + num(gaugeStepMm) + " mm is outside 0.5 .. 100 mm");
}

int RefinementProposal::gaugePointCount() const {
    int n = 0;
    for (const RefinementBar& b : bars)
        n += static_cast<int>(b.zMm.size());
    return n;
}

std::array<FactorCoding, 3> refinementRegion(const FeedScheduleRequest& r) {
    return {FactorCoding::at(r.depthMm), FactorCoding::spanning(r.feedMinMmPerRev, r.feedMaxMmPerRev),
            FactorCoding::spanning(std::min(r.zStartMm, r.zEndMm), std::max(r.zStartMm, r.zEndMm))};
}

DeformationSamples samplesInRegion(const DeformationSamples& s, const std::array<FactorCoding, 3>& region) {
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < s.size(); ++i) {
        const bool depth = std::abs(s.depthMm(i) - region[0].centre) <= kSameDepthMm;
        const bool feed = s.feedMmPerRev(i) >= region[1].min && s.feedMmPerRev(i) <= region[1].max;
        const bool z = s.zMm(i) >= region[2].min && s.zMm(i) <= region[2].max;
        if (depth && feed && z) keep.push_back(i);
    }
    DeformationSamples out;
    const auto n = static_cast<Eigen::Index>(keep.size());
    out.depthMm.resize(n);
    out.feedMmPerRev.resize(n);
    out.zMm.resize(n);
    out.deformationUm.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const Eigen::Index i = keep[static_cast<std::size_t>(k)];
        out.depthMm(k) = region[0].centre;  // exactly the held depth
        out.feedMmPerRev(k) = s.feedMmPerRev(i);
        out.zMm(k) = s.zMm(i);
        out.deformationUm(k) = s.deformationUm(i);
    }
    return out;
}

RefinementProposal proposeRefinement(const FeedSchedule& schedule, const FeedScheduleRequest& request,
                                     const DeformationSamples& measured, double sigmaUm,
                                     const FeedRefinementOptions& options) {
    options.validate();
    if (schedule.segments.empty()) throw std::invalid_argument("a refinement needs a schedule with segments");
    if (!std::isfinite(sigmaUm) || !(sigmaUm > 0.0))
        throw std::invalid_argument("the scatter of a measurement must be above 0 µm (got " + num(sigmaUm) + ")");
    RefinementProposal plan;
    plan.depthMm = request.depthMm;
    plan.region = refinementRegion(request);
    plan.sigmaUm = sigmaUm;
    const double marginPct = std::max(kFeedScheduleTolerancePct - schedule.modelDeviationPct(), kSmallestMarginPct);
    plan.marginUm = marginPct / 100.0 * schedule.levelUm;
    plan.targetHalfWidthUm = 0.5 * plan.marginUm;

    const DeformationModel shape(
        plan.region, deformationTerms(kRefinementTermSet),
        Eigen::VectorXd::Zero(static_cast<Eigen::Index>(deformationTerms(kRefinementTermSet).size())));
    const DeformationSamples here = samplesInRegion(measured, plan.region);
    std::set<double> feedLevels(here.feedMmPerRev.data(), here.feedMmPerRev.data() + here.feedMmPerRev.size());
    plan.measurementsBefore = static_cast<int>(here.size());
    plan.feedLevelsBefore = static_cast<int>(feedLevels.size());
    const std::vector<double> hereFeeds(here.feedMmPerRev.data(), here.feedMmPerRev.data() + here.size());
    const std::vector<double> hereZ(here.zMm.data(), here.zMm.data() + here.size());
    PredictionVarianceDesign design(rowsAt(shape, request.depthMm, hereFeeds, hereZ),
                                    passRows(shape, schedule, request.depthMm));
    auto halfWidth = [&] { return kPlanQuantile * sigmaUm * std::sqrt(design.largestVarianceFactor()); };
    plan.halfWidthBeforeUm = halfWidth();

    const std::vector<double> feeds = candidateFeeds(request);
    const std::vector<double> gauges = candidateGauges(plan.region[2], options.gaugeStepMm);
    for (int b = 0; b < options.maxBarsPerRound; ++b) {
        // Until the local model has its feed levels, every bar brings a new one.
        const bool newFeedOnly =
            static_cast<int>(feedLevels.size()) < options.minFeedLevels &&
            std::any_of(feeds.begin(), feeds.end(), [&](double f) { return feedLevels.count(f) == 0; });
        RefinementBar bar =
            bestBar(design, shape, request.depthMm, feeds, gauges, options.gaugesPerBar, feedLevels, newFeedOnly);
        design.add(rowsAt(shape, request.depthMm, std::vector<double>(bar.zMm.size(), bar.feedMmPerRev), bar.zMm));
        feedLevels.insert(bar.feedMmPerRev);
        plan.bars.push_back(std::move(bar));
        if (halfWidth() <= plan.targetHalfWidthUm && static_cast<int>(feedLevels.size()) >= options.minFeedLevels)
            break;
    }
    plan.halfWidthAfterUm = halfWidth();
    return plan;
}

}  // namespace tt::core
