// The force-deformation experiment on the shaft-turning simulator (preset feed-scheduling), the model
// fitted to it, the schedule made from the model and the scheduled pass machined on the simulator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "config/feed_schedule_config.h"
#include "config/preset_library.h"
#include "core/sim/shaft/deformation_experiment.h"
#include "core/sim/shaft/feed_schedule_check.h"
#include "core/sim/shaft/lathe_pass.h"
#include "core/sim/shaft/lathe_simulator.h"

namespace tt::core {
namespace {

const config::FeedSchedulingSetup& preset() {
    static const config::FeedSchedulingSetup s =
        config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(QStringLiteral("feed-scheduling")));
    return s;
}

const DeformationSamples& experiment() {
    static const DeformationSamples s = runDeformationExperiment(preset().lathe, preset().experiment);
    return s;
}

const DeformationFit& fitted() {
    static const DeformationFit f = fitDeformationModel(experiment(), DeformationTermSet::CubicZ, true);
    return f;
}

DeformationSamples rows(const DeformationSamples& s, const std::vector<Eigen::Index>& which) {
    DeformationSamples out;
    const auto n = static_cast<Eigen::Index>(which.size());
    out.depthMm.resize(n);
    out.feedMmPerRev.resize(n);
    out.zMm.resize(n);
    out.deformationUm.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index r = which[static_cast<std::size_t>(i)];
        out.depthMm(i) = s.depthMm(r);
        out.feedMmPerRev(i) = s.feedMmPerRev(r);
        out.zMm(i) = s.zMm(r);
        out.deformationUm(i) = s.deformationUm(r);
    }
    return out;
}

TEST(LathePass, IsTheSimulatorsOwnCutAtOneFeed) {
    // The pass and the part-to-part simulator share the physics: with warm-up, wear and the tool setting
    // switched off, the simulator's finished diameter error is 2 Y of the pass at every node.
    LatheSetup setup = preset().lathe;
    setup.warmUp.diameterShiftMm = 0.0;
    setup.wear.diameterGrowthMm = 0.0;
    setup.toolSettingOffsetMm = 0.0;
    setup.cutting.depthOfCutMm = 1.5;
    setup.cutting.feedMmPerRev = 0.2;
    const LatheSimulator simulator(setup, {200.0}, LatheDisturbanceModel::none(1));
    const LathePass pass(setup, 1.5);
    const std::vector<double> error = simulator.deterministicErrorMm(1);
    for (std::size_t i = 0; i < error.size(); i += 7)
        EXPECT_NEAR(error[i], 2.0 * pass.deformationMm(simulator.gridZMm()[i], 0.2), 1e-12)
            << "z " << simulator.gridZMm()[i];
    EXPECT_THROW(pass.deformationMm(-1.0, 0.2), std::invalid_argument);
    EXPECT_THROW(pass.deformationMm(100.0, 0.0), std::invalid_argument);
    EXPECT_THROW(LathePass(setup, 0.0), std::invalid_argument);
}

TEST(DeformationExperiment, FamilyFallsFromZmaxToZminAsInThePaper) {
    // Paper 004: the tool travels from zmax to zmin and the deformation falls on the way, for every feed
    // of [fmin, fmax] (Fig. 1). Here the tailstock centre (z = 400 mm, 8 kN/mm) is the softest support,
    // so Y is largest near it and falls towards the stiff headstock over the whole gauged length.
    const config::FeedSchedulingSetup& s = preset();
    for (double a : s.experiment.depthsMm) {
        const LathePass pass(s.lathe, a);
        for (double f : s.experiment.feedsMmPerRev) {
            for (std::size_t i = 1; i < s.experiment.zMm.size(); ++i)
                EXPECT_GT(pass.deformationMm(s.experiment.zMm[i], f), pass.deformationMm(s.experiment.zMm[i - 1], f))
                    << "a " << a << " f " << f << " z " << s.experiment.zMm[i];
            EXPECT_GT(pass.deformationMm(200.0, f + 0.01), pass.deformationMm(200.0, f));  // more feed, more force
        }
    }
}

TEST(DeformationExperiment, OneBarPerDepthAndFeedGaugedWithNoise) {
    const config::FeedSchedulingSetup& s = preset();
    const DeformationSamples& e = experiment();
    ASSERT_EQ(e.size(), static_cast<Eigen::Index>(s.experiment.depthsMm.size() * s.experiment.feedsMmPerRev.size() *
                                                  s.experiment.zMm.size()));
    // The readings scatter about the physics by the micrometer's error: sigma = error95 / 1.96 on the
    // diameter, half of it on Y (plus the 1 µm display step, 0.5 µm on Y: sd 0.5/sqrt(12)).
    double sum = 0.0;
    double sumSquares = 0.0;
    for (Eigen::Index i = 0; i < e.size(); ++i) {
        const double truth = 1000.0 * LathePass(s.lathe, e.depthMm(i)).deformationMm(e.zMm(i), e.feedMmPerRev(i));
        sum += e.deformationUm(i) - truth;
        sumSquares += std::pow(e.deformationUm(i) - truth, 2);
        if (i > 200) break;
    }
    const double n = 202.0;
    const double expected = std::sqrt(std::pow(1000.0 * s.lathe.micrometer.error95Mm / 1.96 / 2.0, 2) + 0.25 / 12.0);
    EXPECT_NEAR(std::sqrt(sumSquares / n), expected, 0.15 * expected);
    EXPECT_NEAR(sum / n, 0.0, 3.0 * expected / std::sqrt(n));
    // Reproducible for its seed, different for another.
    DeformationExperimentPlan other = s.experiment;
    EXPECT_EQ(runDeformationExperiment(s.lathe, other).deformationUm, e.deformationUm);
    other.seed += 1;
    EXPECT_NE(runDeformationExperiment(s.lathe, other).deformationUm, e.deformationUm);
}

TEST(DeformationExperiment, ReportsProgressBarByBarAndStopsWhenAsked) {
    std::vector<std::size_t> done;
    const DeformationSamples all =
        runDeformationExperiment(preset().lathe, preset().experiment, [&](std::size_t bar, std::size_t bars) {
            EXPECT_EQ(bars, 32U);
            done.push_back(bar);
            return true;
        });
    ASSERT_EQ(done.size(), 32U);
    EXPECT_EQ(done.front(), 1U);
    EXPECT_EQ(done.back(), 32U);
    EXPECT_EQ(all.deformationUm, experiment().deformationUm);  // watching does not change the data
    std::size_t calls = 0;
    EXPECT_THROW(runDeformationExperiment(preset().lathe, preset().experiment,
                                          [&](std::size_t bar, std::size_t) {
                                              ++calls;
                                              return bar < 5;
                                          }),
                 DeformationExperimentStopped);
    EXPECT_EQ(calls, 5U);
}

TEST(DeformationModel, SlicesAreTheModel) {
    const DeformationModel& m = fitted().model;
    for (double a : {0.6, 1.5}) {
        for (double f : {0.07, 0.33}) {
            const ScaledPolynomial alongZ = m.alongAxis(a, f);
            for (double z : {25.0, 200.0, 385.0}) {
                EXPECT_NEAR(alongZ.value(z), m.deformationUm(a, f, z), 1e-10);
                EXPECT_NEAR(m.againstFeed(a, z).value(f), m.deformationUm(a, f, z), 1e-10);
            }
        }
    }
}

TEST(DeformationModel, HeldOutPointsWithinTheStatedTwoSigma) {
    // Every fifth measurement is held out, the model is fitted on the rest (cubic in z, stepwise), and
    // the held-out measurements are predicted. The model states 2 sigma of its residuals as the band of
    // a new measurement; for a model that is right about itself about 95 % of new points fall inside
    // (binomial sd about 1.4 % for these 244 points), none far outside.
    const DeformationSamples& e = experiment();
    std::vector<Eigen::Index> train;
    std::vector<Eigen::Index> held;
    for (Eigen::Index i = 0; i < e.size(); ++i)
        (i % 5 == 0 ? held : train).push_back(i);
    const DeformationFit fit = fitDeformationModel(rows(e, train), DeformationTermSet::CubicZ, true);
    const DeformationSamples test = rows(e, held);
    int inside = 0;
    double worst = 0.0;
    for (Eigen::Index i = 0; i < test.size(); ++i) {
        const double error = std::abs(fit.model.deformationUm(test.depthMm(i), test.feedMmPerRev(i), test.zMm(i)) -
                                      test.deformationUm(i));
        inside += error <= fit.twoSigmaUm() ? 1 : 0;
        worst = std::max(worst, error);
    }
    const double share = static_cast<double>(inside) / static_cast<double>(test.size());
    std::printf("held out: %d of %ld within 2 sigma = %.3f um (%.1f %%), worst %.3f um = %.2f sigma\n", inside,
                static_cast<long>(test.size()), fit.twoSigmaUm(), 100.0 * share, worst, 2.0 * worst / fit.twoSigmaUm());
    EXPECT_GE(share, 0.92);
    EXPECT_LT(worst, 2.0 * fit.twoSigmaUm());  // under 4 sigma
    // The fit's own statistics: R² close to 1 and F far above its table value.
    EXPECT_GT(fit.regression.r2, 0.99);
    EXPECT_GT(fit.regression.fStatistic, 100.0 * fit.regression.fCritical95);
}

TEST(DeformationModel, BetweenTheLevelsTooOnANewExperiment) {
    // New bars at depths and feeds between the experiment's levels (another seed): the model interpolates
    // within its 2 sigma for most of them.
    DeformationExperimentPlan between = preset().experiment;
    between.depthsMm = {0.75, 1.25, 1.75};
    between.feedsMmPerRev = {0.075, 0.175, 0.275, 0.375};
    between.seed = 77;
    const DeformationSamples fresh = runDeformationExperiment(preset().lathe, between);
    int inside = 0;
    double worst = 0.0;
    for (Eigen::Index i = 0; i < fresh.size(); ++i) {
        const double error =
            std::abs(fitted().model.deformationUm(fresh.depthMm(i), fresh.feedMmPerRev(i), fresh.zMm(i)) -
                     fresh.deformationUm(i));
        inside += error <= fitted().twoSigmaUm() ? 1 : 0;
        worst = std::max(worst, error);
    }
    const double share = static_cast<double>(inside) / static_cast<double>(fresh.size());
    std::printf("between levels: %.1f %% within 2 sigma, worst %.2f sigma\n", 100.0 * share,
                2.0 * worst / fitted().twoSigmaUm());
    EXPECT_GE(share, 0.9);
}

TEST(FeedSchedule, OnTheFittedModelEveryBreakpointIsAtTheLevel) {
    const FeedScheduleRequest& r = preset().request;
    const FeedSchedule s = scheduleFeed(fitted().model, r);
    ASSERT_GE(s.segments.size(), 10U);
    EXPECT_DOUBLE_EQ(s.segments.front().zFromMm, r.zStartMm);
    EXPECT_DOUBLE_EQ(s.segments.back().zToMm, r.zEndMm);
    for (std::size_t i = 0; i < s.segments.size(); ++i) {
        const FeedSegment& g = s.segments[i];
        // Every segment starts where Y = Yc with its feed (the root solved to full precision) ...
        EXPECT_NEAR(g.yFromUm, s.levelUm, 1e-9 * s.levelUm) << i;
        // ... its feed is the start feed plus whole steps (eq. (2)), rising ...
        const double steps = (g.feedMmPerRev - s.feedStartMmPerRev) / r.feedStepMmPerRev;
        EXPECT_NEAR(steps, std::round(steps), 1e-9) << i;
        if (i > 0) {
            EXPECT_GT(g.feedMmPerRev, s.segments[i - 1].feedMmPerRev);
            EXPECT_DOUBLE_EQ(g.zFromMm, s.segments[i - 1].zToMm);
        }
        // ... it is at least L_min long, and Y stays at or below Yc along it.
        EXPECT_GE(g.lengthMm(), r.minLengthMm) << i;
        for (int k = 0; k <= 20; ++k) {
            const double z = g.zFromMm + (g.zToMm - g.zFromMm) * k / 20.0;
            EXPECT_LE(fitted().model.deformationUm(r.depthMm, g.feedMmPerRev, z), s.levelUm + 1e-9) << i << " " << z;
        }
    }
    EXPECT_LT(s.segments.back().feedMmPerRev, s.feedEndMmPerRev);
}

TEST(FeedSchedule, BothEndsOfTheLevelRangeCanBeScheduledOnEveryExperiment) {
    // Yc = Y1 starts at fmin and Yc = Y2 ends at fmax exactly: rounding in the fitted polynomial must not
    // make either "no feed gives Yc" (it did for seed 6 before Y1, Y2 and the feeds came from the same
    // polynomials). Eight experiments, both ends, and the middle checked on the simulator.
    const FeedScheduleRequest base = preset().request;
    const LathePass pass(preset().lathe, base.depthMm);
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        DeformationExperimentPlan plan = preset().experiment;
        plan.seed = seed;
        const DeformationFit fit =
            fitDeformationModel(runDeformationExperiment(preset().lathe, plan), DeformationTermSet::CubicZ, true);
        for (double q : {0.0, 0.5, 1.0}) {
            FeedScheduleRequest r = base;
            r.levelFraction = q;
            const FeedSchedule s = scheduleFeed(fit.model, r);
            if (q == 0.0) {
                EXPECT_DOUBLE_EQ(s.feedStartMmPerRev, r.feedMinMmPerRev) << seed;
            }
            if (q == 1.0) {
                EXPECT_DOUBLE_EQ(s.feedEndMmPerRev, r.feedMaxMmPerRev) << seed;
            }
            EXPECT_LT(checkFeedSchedule(pass, s, r).maxDeviationPct, 10.0) << "seed " << seed << " q " << q;
        }
    }
}

TEST(FeedSchedule, MachinedOnTheSimulatorStaysWithinTenPercentOfTheLevel) {
    const FeedScheduleRequest& r = preset().request;
    const FeedSchedule s = scheduleFeed(fitted().model, r);
    const LathePass pass(preset().lathe, r.depthMm);
    const FeedScheduleCheck check = checkFeedSchedule(pass, s, r);
    const MachiningTimes t = machiningTimes(s, r, preset().job.spindleRpm);
    std::printf(
        "Yc %.2f um: worst %.2f %% at z %.1f mm; fmax +%.1f %%; fmin -%.1f %%; time %.1f s, fmin %.1f s, "
        "fmax %.1f s, saved %.1f %%\n",
        s.levelUm, check.maxDeviationPct, check.worstZMm, check.feedMaxExcessPct, check.feedMinShortfallPct,
        t.scheduleS, t.feedMinS, t.feedMaxS, t.savedVsFeedMinPct());
    // Paper 004's claim on the simulator: within +-10 % of Yc along the whole scheduled length ...
    EXPECT_LT(check.maxDeviationPct, 10.0);
    EXPECT_LE(std::min(r.zStartMm, r.zEndMm), check.worstZMm);
    EXPECT_GE(std::max(r.zStartMm, r.zEndMm), check.worstZMm);
    // ... while constant fmax exceeds it and constant fmin takes longer.
    EXPECT_GT(check.feedMaxExcessPct, 10.0);
    EXPECT_GT(t.feedMinS, t.scheduleS);
    EXPECT_GT(t.savedVsFeedMinPct(), 30.0);
    EXPECT_GT(t.scheduleS, t.feedMaxS);
    // The check covers the pass densely: every node of the shaft model inside it (2.5 mm apart) plus both
    // sides of every breakpoint.
    ASSERT_EQ(check.zMm.size(), check.scheduleUm.size());
    // (the 127 nodes strictly inside 60 .. 380 mm; a breakpoint may fall on one of them).
    EXPECT_GE(check.zMm.size(), 2 * s.segments.size() + 126);
}

TEST(FeedScheduleCheck, RefusesAPassOfAnotherDepth) {
    const FeedScheduleRequest& r = preset().request;
    const FeedSchedule s = scheduleFeed(fitted().model, r);
    EXPECT_THROW(checkFeedSchedule(LathePass(preset().lathe, 1.0), s, r), std::invalid_argument);
    EXPECT_THROW(checkFeedSchedule(LathePass(preset().lathe, r.depthMm), FeedSchedule{}, r), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
