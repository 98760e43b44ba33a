// An interrupted run is offered for resume when the application starts (issue 17 item 10): a real SQLite
// history holds a run of the simulated lathe that was cut off (still "running"); the start asks whether to
// continue it from the part after its last stored one; No leaves it, Yes continues it on the Run page
// through core::resumeShaftRun with its stored settings, and every part ends up stored once.
#include "ui/run/interrupted_run.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QProcess>
#include <QTest>
#include <functional>
#include <set>

#include "config/loop_scenario.h"
#include "core/storage/data_stores.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "run_window.h"
#include "screenshots.h"
#include "tests/support/patient_wait.h"
#include "ui/run/run_session.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

constexpr qint64 kPlannedParts = 16;
constexpr qint64 kPartsBeforeCut = 6;

bool waitFor(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs) return false;
        QTest::qWait(5);
    }
    return true;
}

class InterruptedRunTest : public test::RunWindowTest {
protected:
    /// Runs the simulated lathe with the history of `context` until kPartsBeforeCut parts are finished and
    /// drops everything without stopping: the run stays "running", as after a power cut.
    void makeInterruptedRun() {
        RunSettings s;
        s.preset = QStringLiteral("paper-2012-group1");
        s.controller = QStringLiteral("lqg");
        s.delay = 2;
        s.seed = 7;
        s.machineKey = QStringLiteral("simulated-lathe");
        const config::LoopScenario scenario = config::loadLoopScenario(s.preset, s.delay);
        const core::ShaftRunPlan plan =
            core::planShaftRun(scenario, {core::ControllerKind::Lqg, std::nullopt, kPlannedParts});
        std::optional<devices::ShaftMachineOffer> offer;
        for (const devices::ShaftMachineOffer& o : devices.shaftMachineOffers())
            if (o.key == s.machineKey) offer = o;
        ASSERT_TRUE(offer.has_value());
        std::unique_ptr<core::ShaftMachine> machine = offer->make(scenario, s.seed, 3600.0);
        storage::Database database(storage::DataStores(context.databasePath).config());
        storage::SqlHistoryStore history(database);
        std::unique_ptr<core::LoopEngine> engine = core::buildShaftRun(scenario, plan, *machine, &history);
        engine->start(storedRunDescription(s, plan));
        ASSERT_TRUE(waitFor(
            [&] {
                engine->step();
                return engine->partsFinished() >= kPartsBeforeCut;
            },
            tt::test::kPatientWaitMs));
    }
};

TEST_F(InterruptedRunTest, StartOffersTheInterruptedRunAndYesContinuesItWithEveryPartStoredOnce) {
    makeInterruptedRun();
    const std::optional<InterruptedRun> found = findInterruptedRun(context);
    ASSERT_TRUE(found.has_value());
    const qint64 runId = found->point.run.runId;
    const qint64 next = found->nextPart();
    EXPECT_GE(next, kPartsBeforeCut - 2) << "the parts the controller has used are the resume point";
    EXPECT_EQ(found->settings.lastPartNumber, std::optional<qint64>(kPlannedParts));
    EXPECT_EQ(found->settings.seed, 7u);

    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    // No: the run is left as it is.
    prompt.answers.push_back(Prompt::Answer::No);
    EXPECT_FALSE(offerInterruptedRun(context, window));
    EXPECT_EQ(prompt.log.back(), QStringLiteral("ask: Interrupted run"));
    const QString expected = QStringLiteral(
                                 "Run %1 (simulated lathe, paper-2012-group1, %2 of %3 parts done) was "
                                 "interrupted. Continue it from part %4?")
                                 .arg(runId)
                                 .arg(found->point.run.partCount)
                                 .arg(kPlannedParts)
                                 .arg(next);
    EXPECT_EQ(prompt.lastText, expected);
    QTest::qWait(200);
    EXPECT_EQ(page->session().snapshot().state, core::LoopState::Idle);
    EXPECT_EQ(context.data().history()->runs().front().status, "running");

    // Yes: the Run page continues it at part `next`, to its planned end.
    std::set<qint64> startedParts;
    QObject::connect(&page->session(), &RunSession::loopEvent, &window, [&](const core::LoopEvent& e) {
        if (e.kind == core::LoopEvent::Kind::PartStarted) startedParts.insert(e.partNumber);
    });
    prompt.answers.push_back(Prompt::Answer::Yes);
    ASSERT_TRUE(offerInterruptedRun(context, window));
    ASSERT_TRUE(waitFor([&] { return context.data().history()->runs().front().status == "complete"; },
                        tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    ASSERT_FALSE(startedParts.empty());
    EXPECT_EQ(*startedParts.begin(), next) << "the first part machined after the resume";
    EXPECT_EQ(*startedParts.rbegin(), kPlannedParts);
    EXPECT_EQ(page->session().snapshot().runId, std::optional<qint64>(runId)) << "the same run, no new one";
    const std::vector<core::RunSummary> runs = context.data().history()->runs();
    EXPECT_EQ(runs.size(), 1u);
    const std::vector<core::StoredPart> parts = context.data().history()->parts(runId);
    std::set<qint64> numbers;
    for (const core::StoredPart& p : parts) {
        EXPECT_TRUE(numbers.insert(p.partNumber).second) << "part " << p.partNumber << " stored twice";
        EXPECT_TRUE(p.measurement.has_value()) << "part " << p.partNumber << " measured";
    }
    EXPECT_EQ(numbers.size(), static_cast<std::size_t>(kPlannedParts));
    EXPECT_EQ(*numbers.begin(), 1);
    EXPECT_EQ(*numbers.rbegin(), kPlannedParts);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_resumed")));
}

TEST_F(InterruptedRunTest, AFinishedRunIsNotOffered) {
    makeInterruptedRun();
    {
        storage::Database database(storage::DataStores(context.databasePath).config());
        storage::SqlHistoryStore history(database);
        history.finishRun(history.runs().front().runId, "stopped");
    }
    EXPECT_FALSE(findInterruptedRun(context).has_value());
    MainWindow window(context);
    EXPECT_FALSE(offerInterruptedRun(context, window));
    EXPECT_TRUE(prompt.log.isEmpty()) << "nothing asked";
}

TEST_F(InterruptedRunTest, ARunOfTheCommandLineCutOffByCtrlCIsOfferedAndContinues) {
    // `trueturn simulate --db` on the physical-lathe preset, interrupted as Ctrl-C does (SIGTERM: the run
    // stops after its current part and stays resumable).
    QProcess simulate;
    simulate.start(QStringLiteral(TRUETURN_EXE),
                   {QStringLiteral("simulate"), QStringLiteral("--db"), context.databasePath,
                    QStringLiteral("--preset"), QStringLiteral("paper-2012-group1"), QStringLiteral("--parts"),
                    QStringLiteral("400"), QStringLiteral("--warmup"), QStringLiteral("0"), QStringLiteral("--seed"),
                    QStringLiteral("3"), QStringLiteral("--speed"), QStringLiteral("3600")});
    ASSERT_TRUE(simulate.waitForStarted(tt::test::kPatientWaitMs));
    ASSERT_TRUE(waitFor(
        [&] {
            const std::optional<InterruptedRun> run = findInterruptedRun(context);
            return run && run->point.lastPartNumber >= 5;
        },
        tt::test::kPatientWaitMs));
    simulate.terminate();
    ASSERT_TRUE(simulate.waitForFinished(tt::test::kPatientWaitMs));
    EXPECT_EQ(simulate.exitCode(), 130) << simulate.readAllStandardError().toStdString();

    const std::optional<InterruptedRun> found = findInterruptedRun(context);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->settings.lastPartNumber, std::optional<qint64>(400)) << "warm-up 0 + 400 parts";
    EXPECT_EQ(found->settings.seed, 3u);
    const qint64 runId = found->point.run.runId;
    const qint64 next = found->nextPart();
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    std::set<qint64> startedParts;
    QObject::connect(&page->session(), &RunSession::loopEvent, &window, [&](const core::LoopEvent& e) {
        if (e.kind == core::LoopEvent::Kind::PartStarted) startedParts.insert(e.partNumber);
    });
    prompt.answers.push_back(Prompt::Answer::Yes);
    ASSERT_TRUE(offerInterruptedRun(context, window));
    EXPECT_TRUE(prompt.lastText.endsWith(
        QStringLiteral("of 400 parts done) was interrupted. Continue it from part %1?").arg(next)))
        << prompt.lastText.toStdString();
    ASSERT_TRUE(waitFor([&] { return page->session().snapshot().partsFinished >= 5; }, tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    page->session().stop();
    ASSERT_TRUE(
        waitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; }, tt::test::kPatientWaitMs));
    ASSERT_FALSE(startedParts.empty());
    EXPECT_EQ(*startedParts.begin(), next);
    EXPECT_EQ(context.data().history()->runs().size(), 1u) << "the same run, no new one";
    std::set<qint64> numbers;
    for (const core::StoredPart& p : context.data().history()->parts(runId))
        EXPECT_TRUE(numbers.insert(p.partNumber).second) << "part " << p.partNumber << " stored twice";
    ASSERT_FALSE(numbers.empty());
    EXPECT_EQ(*numbers.begin(), 1);
    EXPECT_EQ(static_cast<qint64>(numbers.size()), *numbers.rbegin()) << "no part missing";
}

}  // namespace
}  // namespace tt::ui
