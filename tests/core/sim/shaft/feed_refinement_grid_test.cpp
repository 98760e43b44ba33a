// The feed schedule refined until its pass holds +-10 % of Yc on the simulator, on a reduced grid of the
// one docs/BENCHMARKS.md records in full (scripts/feed-schedule-grid.py: depths 0.5 .. 2 mm, Q = 0, 0.5, 1,
// feed steps 0.005 and 0.01 mm/rev, experiment seeds 1 .. 8, 240 cells). Every depth, every level fraction,
// both feed steps and six seeds appear once; the cells where the model alone misses are among them.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "config/feed_schedule_config.h"
#include "config/preset_library.h"
#include "core/sim/shaft/deformation_experiment.h"
#include "core/sim/shaft/feed_refinement.h"

namespace tt::core {
namespace {

struct Cell {
    double depthMm;
    double levelFraction;
    double feedStepMmPerRev;
    std::uint64_t seed;
};

const config::FeedSchedulingSetup& preset() {
    static const config::FeedSchedulingSetup s =
        config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(QStringLiteral("feed-scheduling")));
    return s;
}

class RefinedGrid : public ::testing::TestWithParam<Cell> {};

TEST_P(RefinedGrid, HoldsTenPercentOfTheLevel) {
    const Cell c = GetParam();
    DeformationExperimentPlan plan = preset().experiment;
    plan.seed = c.seed;
    const DeformationSamples samples = runDeformationExperiment(preset().lathe, plan);
    const DeformationFit fit = fitDeformationModel(samples, DeformationTermSet::CubicZ, true);
    FeedScheduleRequest r = preset().request;
    r.depthMm = c.depthMm;
    r.levelFraction = c.levelFraction;
    r.feedStepMmPerRev = c.feedStepMmPerRev;
    r.switchRule = FeedSwitchRule::Centred;
    const FeedRefinementOptions options;  // 3 rounds of at most 6 bars, 33 gauge points each
    const FeedRefinement refined =
        refineFeedSchedule(preset().lathe, fit.model, fit.regression.residualSigma, samples, r, options, c.seed);
    const FeedScheduleCheck& result = refined.lastScheduled() ? *refined.lastScheduled()->check : refined.initialCheck;
    std::printf("a %.2f Q %.1f f_mm %.3f seed %llu: %.2f %% -> %.2f %% in %zu rounds, %d bars\n", c.depthMm,
                c.levelFraction, c.feedStepMmPerRev, static_cast<unsigned long long>(c.seed),
                refined.initialCheck.maxDeviationPct, result.maxDeviationPct, refined.rounds.size(),
                refined.barCount());
    EXPECT_LE(result.maxDeviationPct, kFeedScheduleTolerancePct);
    EXPECT_TRUE(refined.withinTolerance());
    EXPECT_LE(static_cast<int>(refined.rounds.size()), options.maxRounds);
    EXPECT_TRUE(refined.advice.empty()) << refined.advice;
    if (refined.rounds.empty()) {
        EXPECT_LE(refined.initialCheck.maxDeviationPct, kFeedScheduleTolerancePct);
    } else {
        EXPECT_GT(refined.initialCheck.maxDeviationPct, kFeedScheduleTolerancePct);  // refined only when it missed
        EXPECT_GT(refined.barCount(), 0);
    }
}

// a = 0.5 mm at Q = 0 and 0.5 misses with the model alone (13 .. 24 % on seeds 1 .. 8, the level of 6 .. 8 µm
// is small next to the model's error); 0.75 mm has no bar of the experiment; 2.0 mm at Q = 0 and f_mm 0.01
// is at the edge (about 11 %).
INSTANTIATE_TEST_SUITE_P(PaperFour, RefinedGrid,
                         ::testing::Values(Cell{0.5, 0.0, 0.01, 1}, Cell{0.5, 0.5, 0.005, 8}, Cell{0.75, 0.0, 0.01, 2},
                                           Cell{1.0, 1.0, 0.01, 3}, Cell{1.5, 0.5, 0.005, 5}, Cell{2.0, 0.0, 0.01, 7}));

}  // namespace
}  // namespace tt::core
