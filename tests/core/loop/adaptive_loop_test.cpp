// The adaptive loop in the loop engine (core/loop/adaptive_loop.h) on the built-in statistical lathe: on a model
// mismatch the loop switches bumplessly to its fallback, identifies the plant, applies (adapt) or proposes
// (propose) a design whose margins hold, records it, and a resumed run continues with it.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <set>

#include "core/loop/loop_engine.h"
#include "core/run/shaft_run.h"
#include "core/run/shaft_run_builder.h"
#include "core/run/shaft_study.h"
#include "core/run/simulated_lathe.h"
#include "tests/core/support/loop_test_support.h"
#include "tests/core/support/lqg_test_support.h"

namespace tt::core {
namespace {

/// paper-2012 on the statistical lathe (the model is the plant), with the plant's gain factor and delay.
ShaftScenario paperScenario(int z, double gainFactor, std::optional<int> plantDelay, MismatchAction action) {
    ShaftScenario s;
    s.control = test::paper2012Setup(z);
    s.plantMismatch.gainFactor = gainFactor;
    s.plantMismatch.delayParts = plantDelay;
    s.mismatchMonitor.action = action;
    return s;
}

/// Every part's corrections as started, and the engine's notices.
struct Watch final : LoopListener {
    std::map<std::int64_t, std::vector<PointCorrectionRecord>> started;
    std::vector<LoopEvent> adaptations;
    LoopEngine* engine = nullptr;
    bool acceptProposals = false;
    std::int64_t stopAfter = 0;
    std::atomic<bool>* stop = nullptr;
    void onLoopEvent(const LoopEvent& e) override {
        if (e.kind == LoopEvent::Kind::PartStarted) started[e.partNumber] = e.corrections;
        if (e.kind == LoopEvent::Kind::Alarm && e.alarmKind == kAdaptationAlarm) {
            adaptations.push_back(e);
            if (acceptProposals && e.notice.kind == NoticeKind::AdaptationProposed && engine) {
                EXPECT_TRUE(engine->acceptProposal());
            }
        }
        if (stop && stopAfter > 0 && e.kind == LoopEvent::Kind::PartFinished && e.partNumber >= stopAfter) *stop = true;
    }
};

LatheRunRecord run(const ShaftScenario& s, std::int64_t parts, Watch& watch, HistoryStore* history = nullptr) {
    LatheRunSpec spec;
    spec.scenario = s;
    spec.seed = 1;
    spec.plan = planShaftRun(s, {ControllerKind::Lqg, std::nullopt, parts});
    spec.listener = &watch;
    spec.history = history;
    spec.stop = watch.stop;
    return runLatheLoop(std::move(spec));
}

/// Every switch is bumpless: from the part a controller takes over to kSwitchWatchParts after it, no correction
/// was limited (computed = applied) and no step between parts exceeds the limiter's step.
void expectBumpless(const Watch& w, const LatheRunRecord& r, double maxStepMm) {
    for (const AdaptationRecord& a : r.adaptations) {
        if (!a.applied) continue;
        for (std::int64_t p = a.partNumber; p < a.partNumber + kSwitchWatchParts && w.started.count(p); ++p) {
            const auto& now = w.started.at(p);
            const auto& before = w.started.at(p - 1);
            for (std::size_t i = 0; i < now.size(); ++i) {
                EXPECT_DOUBLE_EQ(now[i].computedMm, now[i].appliedMm) << "part " << p << " point " << i + 1;
                EXPECT_LE(std::abs(now[i].appliedMm - before[i].appliedMm), maxStepMm) << "part " << p;
            }
            if (p == a.partNumber) {  // the first part of the new controller gets the last correction exactly
                for (std::size_t i = 0; i < now.size(); ++i)
                    EXPECT_NEAR(now[i].appliedMm, before[i].appliedMm, 1e-12);
            }
        }
    }
}

/// The records in words, for a failing expectation.
std::string sequence(const LatheRunRecord& r) {
    std::string out;
    for (const AdaptationRecord& a : r.adaptations)
        out += a.kind + "@" + std::to_string(a.partNumber) + " ";
    for (const RecordedAlarm& a : r.modelAlarms)
        out += "alarm@" + std::to_string(a.part) + " ";
    return out;
}

/// The first record of `kind`, null when there is none.
const AdaptationRecord* first(const LatheRunRecord& r, const std::string& kind) {
    for (const AdaptationRecord& a : r.adaptations)
        if (a.kind == kind) return &a;
    return nullptr;
}

/// The model the loop ran on last (the last applied record with a model after it).
const PlantModelRecord* lastModel(const LatheRunRecord& r) {
    const PlantModelRecord* m = nullptr;
    for (const AdaptationRecord& a : r.adaptations)
        if (a.applied && a.modelAfter) m = &*a.modelAfter;
    return m;
}

// A plant of twice the model's gain (z = 1): the monitor fires, the fallback takes over at the next part, the plant
// is identified and the adapted LQG takes over within 300 parts of the alarm; the model the loop ends on has the gain
// 4 within 10 % and the delay 1; every switch is bumpless. (At z = 1 the adapted LQG is close to minimum variance,
// where closed-loop data hardly tell the gain: a later alarm may send the loop through its fallback once more.)
TEST(AdaptiveLoop, AdaptsToTwiceTheGain) {
    Watch w;
    const ShaftScenario s = paperScenario(1, 2.0, std::nullopt, MismatchAction::Adapt);
    const LatheRunRecord r = run(s, 1500, w);
    SCOPED_TRACE(sequence(r));
    ASSERT_TRUE(r.outcome.complete) << r.outcome.stopReason;
    ASSERT_FALSE(r.modelAlarms.empty());
    const AdaptationRecord& fallback = r.adaptations.front();
    EXPECT_EQ(fallback.kind, adaptation_kind::kFallback);
    EXPECT_TRUE(fallback.applied);
    EXPECT_EQ(fallback.partNumber, r.modelAlarms.front().part + s.delay());  // the next part after the alarm
    EXPECT_NEAR(fallback.fallbackWeight, designFallback(1).weight, 1e-12);
    EXPECT_EQ(fallback.modelBefore.points.front().gain, 2.0);
    const AdaptationRecord* adapted = first(r, adaptation_kind::kAdapted);
    ASSERT_NE(adapted, nullptr);
    EXPECT_TRUE(adapted->applied);
    EXPECT_LE(adapted->partNumber - r.modelAlarms.front().part, 300);
    const PlantModelRecord* model = lastModel(r);
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(model->delayParts, 1);
    for (const PointModelRecord& p : model->points)
        EXPECT_NEAR(p.gain, 4.0, 0.4);
    int applied = 0;
    for (const AdaptationRecord& a : r.adaptations)
        applied += a.applied ? 1 : 0;
    EXPECT_EQ(r.switches, applied);
    expectBumpless(w, r, s.control.limits.maxStepMm);
}

// A plant one part slower than the model (z = 2, plant delay 3): identified as delay 3 and adapted with the lag.
TEST(AdaptiveLoop, AdaptsToOneMorePartOfDelay) {
    Watch w;
    const ShaftScenario s = paperScenario(2, 1.0, 3, MismatchAction::Adapt);
    const LatheRunRecord r = run(s, 1500, w);
    SCOPED_TRACE(sequence(r));
    ASSERT_TRUE(r.outcome.complete) << r.outcome.stopReason;
    ASSERT_FALSE(r.modelAlarms.empty());
    const AdaptationRecord* adapted = first(r, adaptation_kind::kAdapted);
    ASSERT_NE(adapted, nullptr);
    ASSERT_TRUE(adapted->modelAfter);
    EXPECT_EQ(adapted->modelAfter->delayParts, 3);
    EXPECT_EQ(adapted->modelAfter->lagParts, 1);
    EXPECT_LE(adapted->partNumber - r.modelAlarms.front().part, 300);
    EXPECT_EQ(r.modelAlarms.size(), 1u) << "the monitor restarted on the new model and stays quiet";
    expectBumpless(w, r, s.control.limits.maxStepMm);
}

// Propose: the fallback takes over and the design waits; the engineer's Apply (acceptProposal) switches to it.
TEST(AdaptiveLoop, ProposesAndTakesTheEngineersApply) {
    const ShaftScenario s = paperScenario(1, 0.5, std::nullopt, MismatchAction::Propose);
    {
        Watch w;
        const LatheRunRecord r = run(s, 1200, w);
        ASSERT_GE(r.adaptations.size(), 2u);
        EXPECT_EQ(r.adaptations[0].kind, adaptation_kind::kFallback);
        EXPECT_EQ(r.adaptations[1].kind, adaptation_kind::kProposed);
        EXPECT_FALSE(r.adaptations[1].applied);
        EXPECT_EQ(r.switches, 1) << "only the fallback took over";
    }
    SimulatedLathe lathe(s.shopSpec(1));
    const ShaftRunPlan plan = planShaftRun(s, {ControllerKind::Lqg, std::nullopt, 1200});
    const auto engine = buildShaftRun(s, plan, lathe, nullptr);
    Watch w;
    w.engine = engine.get();
    w.acceptProposals = true;
    engine->setListener(&w);
    EXPECT_FALSE(engine->acceptProposal());
    engine->start({});
    EXPECT_TRUE(runSimulation(*engine, lathe).complete);
    ASSERT_FALSE(w.adaptations.empty());
    EXPECT_EQ(w.adaptations.back().notice.kind, NoticeKind::ProposalAccepted);
    ASSERT_TRUE(w.adaptations.back().adaptation);
    EXPECT_TRUE(w.adaptations.back().adaptation->applied);
    EXPECT_EQ(engine->adaptation()->phase(), AdaptiveLoop::Phase::Model);
    EXPECT_NE(engine->controllerDescription().find("LQG adapted"), std::string::npos);
}

// A design whose margins fail is not applied (item 3): with a commissioning demand no LQG can meet (a gain margin of
// 100, loop.adaptation.min_gain_margin), every identification's design is refused with the margin named, the
// fallback stays in charge (only its switch happened), is retried later, and the operator's notice says why.
TEST(AdaptiveLoop, ADesignThatFailsItsMarginsIsNotAppliedAndTheFallbackStays) {
    ShaftScenario s = paperScenario(1, 2.0, std::nullopt, MismatchAction::Adapt);
    s.adaptation.minGainMargin = 100.0;
    Watch w;
    const LatheRunRecord r = run(s, 800, w);
    SCOPED_TRACE(sequence(r));
    ASSERT_TRUE(r.outcome.complete) << r.outcome.stopReason;
    ASSERT_GE(r.adaptations.size(), 3u) << "the fallback, then a refused design retried later";
    EXPECT_EQ(r.adaptations.front().kind, adaptation_kind::kFallback);
    int refused = 0;
    for (std::size_t i = 1; i < r.adaptations.size(); ++i) {
        const AdaptationRecord& a = r.adaptations[i];
        EXPECT_EQ(a.kind, adaptation_kind::kRefused);
        EXPECT_FALSE(a.applied);
        EXPECT_NE(a.reason.find("gain margin"), std::string::npos) << a.reason;
        EXPECT_NE(a.reason.find("the 100 the identified gain's uncertainty needs"), std::string::npos) << a.reason;
        EXPECT_EQ(a.notice.kind, NoticeKind::AdaptationRefused);
        EXPECT_EQ(a.notice.cause, a.reason);
        ++refused;
    }
    EXPECT_GE(refused, 2);
    EXPECT_EQ(r.switches, 1) << "only the fallback took over";
    expectBumpless(w, r, s.control.limits.maxStepMm);
}

// Hold and alarm keep their meaning: no adaptation.
TEST(AdaptiveLoop, HoldAndAlarmDoNotAdapt) {
    for (MismatchAction action : {MismatchAction::Hold, MismatchAction::AlarmOnly}) {
        Watch w;
        const LatheRunRecord r = run(paperScenario(1, 2.0, std::nullopt, action), 400, w);
        EXPECT_EQ(r.modelAlarms.size(), 1u);
        EXPECT_TRUE(r.adaptations.empty());
        EXPECT_EQ(r.switches, 0);
    }
}

// The matching plant: no alarm, so nothing adapts (3,000 parts, z = 1..4; the 20,000-part check is in
// scripts/adaptive-grid.py and docs/DECISIONS.md).
TEST(AdaptiveLoop, MatchingPlantDoesNotAdapt) {
    for (int z = 1; z <= 4; ++z) {
        Watch w;
        const LatheRunRecord r = run(paperScenario(z, 1.0, std::nullopt, MismatchAction::Adapt), 3000, w);
        EXPECT_TRUE(r.modelAlarms.empty()) << "z = " << z;
        EXPECT_TRUE(r.adaptations.empty()) << "z = " << z;
    }
}

// The must-show of the plant unlike the model: after adapting, the k_eff of the last 1,000 of 3,000 parts is within
// 15 % of the analytic k_eff of the LQG designed for the true plant (one part more of delay, half and twice the gain;
// seed 1; the full grid z = 1..4 x 3 kinds is scripts/adaptive-grid.py mismatch, ratios 1.002 .. 1.013 measured).
TEST(AdaptiveLoop, AfterAdaptingKEffIsWithinFifteenPercentOfTheTruePlantsLqg) {
    struct Case {
        int z;
        double gainFactor;
        std::optional<int> plantDelay;
    };
    for (const Case& c : {Case{1, 1.0, 2}, Case{2, 0.5, std::nullopt}, Case{3, 2.0, std::nullopt}, Case{4, 1.0, 5}}) {
        const ShaftScenario s = paperScenario(c.z, c.gainFactor, c.plantDelay, MismatchAction::Adapt);
        LatheStudyOptions options;
        options.parts = 1000;
        options.warmupParts = 2000;
        const LatheStudyResult r = runLatheStudy(s, 1, options);
        const double reference = r.kEffTruePlantLqg;
        SCOPED_TRACE("z = " + std::to_string(c.z) + ", gain x " + std::to_string(c.gainFactor) + ", plant delay " +
                     std::to_string(c.plantDelay.value_or(c.z)));
        ASSERT_FALSE(r.adaptations.empty());
        EXPECT_NEAR(r.kEff / reference, 1.0, 0.15) << "k_eff " << r.kEff << ", true plant's LQG " << reference;
        EXPECT_LE(r.maxSwitchStepMm, s.control.limits.maxStepMm);
    }
}

/// The largest gain standard error of the first adapted model, relative to its gain.
double firstDesignsGainUncertainty(const LatheRunRecord& r) {
    const AdaptationRecord* adapted = first(r, adaptation_kind::kAdapted);
    EXPECT_NE(adapted, nullptr) << sequence(r);
    if (!adapted || !adapted->modelAfter) return std::numeric_limits<double>::quiet_NaN();
    double worst = 0.0;
    for (const PointModelRecord& p : adapted->modelAfter->points)
        worst = std::max(worst, p.gainStdErr / p.gain);
    return worst;
}

// The dither (item 2): while the fallback identifies, +- a share of each point's tolerance zone is added to the
// corrections as a pseudo-random binary sequence of the part number. On the same plant (twice the model's gain) and
// seed it makes the first identified gains more certain than without it; once the adapted LQG takes over it stops.
TEST(AdaptiveLoop, TheDitherExcitesThePlantWhileTheFallbackIdentifiesAndStopsAfter) {
    ShaftScenario s = paperScenario(1, 2.0, std::nullopt, MismatchAction::Adapt);
    Watch plain;
    const double without = firstDesignsGainUncertainty(run(s, 600, plain));
    s.adaptation.ditherShare = 0.25;
    Watch dithered;
    const LatheRunRecord r = run(s, 600, dithered);
    const double with = firstDesignsGainUncertainty(r);
    EXPECT_LT(with, 0.5 * without) << "without the dither " << without << ", with it " << with;  // 0.100 / 0.016

    // The dither as the engine adds it: +- 0.25 x the zone's width (0.06 mm) / the model's gain 2 = 0.0075 mm radial
    // on the fallback, both signs; none once the adapted LQG took over.
    SimulatedLathe lathe(s.shopSpec(1));
    const auto engine = buildShaftRun(s, planShaftRun(s, {ControllerKind::Lqg, std::nullopt, 600}), lathe, nullptr);
    struct DitherWatch final : LoopListener {
        const AdaptiveLoop* loop = nullptr;
        std::set<double> onFallback, afterwards;
        void onLoopEvent(const LoopEvent& e) override {
            if (e.kind != LoopEvent::Kind::PartStarted) return;
            const Eigen::VectorXd d = loop->dither(e.partNumber);
            auto& seen = loop->phase() == AdaptiveLoop::Phase::Fallback ? onFallback : afterwards;
            seen.insert(d.begin(), d.end());
        }
    } watch;
    watch.loop = engine->adaptation();
    ASSERT_NE(watch.loop, nullptr);
    engine->setListener(&watch);
    engine->start({});
    EXPECT_TRUE(runSimulation(*engine, lathe).complete);
    EXPECT_EQ(engine->adaptation()->phase(), AdaptiveLoop::Phase::Model);
    ASSERT_EQ(watch.onFallback.size(), 2u);
    EXPECT_NEAR(*watch.onFallback.begin(), -0.0075, 1e-12);
    EXPECT_NEAR(*watch.onFallback.rbegin(), 0.0075, 1e-12);
    EXPECT_EQ(watch.afterwards, std::set<double>{0.0});
}

// Recorded in the history; a run stopped after its adaptation resumes with the adapted controller (its stored state
// restores into it) and completes.
TEST(AdaptiveLoop, RecordedAndResumedWithTheAdaptedController) {
    test::MemoryHistory history;
    const ShaftScenario s = paperScenario(1, 2.0, std::nullopt, MismatchAction::Adapt);
    std::atomic<bool> stop{false};
    Watch first;
    first.stop = &stop;
    first.stopAfter = 900;
    const LatheRunRecord r = run(s, 1500, first, &history);
    ASSERT_TRUE(r.outcome.interrupted);
    ASSERT_TRUE(r.runId);
    const std::vector<AdaptationRecord> stored = history.adaptations(*r.runId);
    ASSERT_EQ(stored.size(), r.adaptations.size());
    ASSERT_TRUE(stored.back().applied && stored.back().modelAfter) << sequence(r);
    bool alarmed = false;
    for (const AlarmRecord& a : history.alarms(*r.runId))
        alarmed = alarmed || a.kind == kAdaptationAlarm;
    EXPECT_TRUE(alarmed);

    const std::optional<ResumePoint> point = history.resumePoint(*r.runId);
    ASSERT_TRUE(point);
    LatheRunSpec spec;
    spec.scenario = s;
    spec.seed = 1;
    spec.plan = planShaftRun(s, {ControllerKind::Lqg, std::nullopt, 1500});
    spec.history = &history;
    spec.resume = point;
    const LatheRunRecord resumed = runLatheLoop(std::move(spec));
    EXPECT_TRUE(resumed.outcome.complete) << resumed.outcome.stopReason;
    for (const AdaptationRecord& a : resumed.adaptations)
        EXPECT_EQ(a.kind, adaptation_kind::kRefined) << "the adapted model holds after the resume (refined at most)";
}

}  // namespace
}  // namespace tt::core
