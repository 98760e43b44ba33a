// An interrupted run is offered for resume when the application starts (issue 17 item 10): a real SQLite
// history holds a run of the simulated lathe that was cut off (still "running"); the start asks whether to
// continue it from the part after its last stored one; No leaves it, Yes continues it on the Run page
// through core::resumeShaftRun with its stored settings, and every part ends up stored once.
#include "ui/run/interrupted_run.h"

#include <gtest/gtest.h>

#include <QComboBox>
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
#include "runtime/run/machine_catalog.h"
#include "runtime/run/run_session.h"
#include "runtime/run/shaft_run_assembly.h"
#include "screenshots.h"
#include "tests/support/patient_wait.h"
#include "tests/support/stored_runs.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

constexpr qint64 kPlannedParts = 16;
constexpr qint64 kPartsBeforeCut = 6;

using test::waitFor;

class InterruptedRunTest : public test::RunWindowTest {
protected:
    /// Runs the simulated lathe with the history of `context` until kPartsBeforeCut parts are finished and
    /// drops everything without stopping: the run stays "running", as after a power cut.
    void makeInterruptedRun() {
        runtime::RunRequest request;
        request.preset = QStringLiteral("paper-2012-group1");
        request.delay = 2;
        request.seed = 7;
        request.endPart = kPlannedParts;
        request.database = context.databasePath;
        const std::optional<runtime::MachineOffer> offer =
            runtime::MachineCatalog(&devices).find(runtime::kBuiltInLatheKey);
        ASSERT_TRUE(offer.has_value());
        storage::Database database(storage::DataStores(context.databasePath).config());
        storage::SqlHistoryStore history(database);
        std::unique_ptr<runtime::AssembledRun> run = runtime::assembleRun(request, offer->prepare(request), &history);
        runtime::startRun(*run);
        while (run->engine->partsFinished() < kPartsBeforeCut)
            run->stepper->advanceTo(1e18, 1);
    }
};

TEST_F(InterruptedRunTest, StartOffersTheInterruptedRunAndYesContinuesItWithEveryPartStoredOnce) {
    makeInterruptedRun();
    const std::optional<runtime::InterruptedRun> found = findInterruptedRun(context);
    ASSERT_TRUE(found.has_value());
    const qint64 runId = found->point.run.runId;
    const qint64 next = found->nextPart();
    EXPECT_GE(next, kPartsBeforeCut - 2) << "the parts the controller has used are the resume point";
    EXPECT_EQ(found->request.endPart, std::optional<std::int64_t>(kPlannedParts));
    EXPECT_EQ(found->request.seed, 7u);

    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    // No: the run is left as it is.
    prompt.answers.push_back(Prompt::Answer::No);
    EXPECT_FALSE(offerInterruptedRun(context, window));
    EXPECT_EQ(prompt.log.back(), QStringLiteral("ask: Interrupted run"));
    const QString expected = QStringLiteral(
                                 "Run %1 (Simulated lathe (built in), paper-2012-group1, %2 of %3 parts done) was "
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
    QObject::connect(&page->session(), &runtime::RunSession::loopEvent, &window, [&](const core::LoopEvent& e) {
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

TEST_F(InterruptedRunTest, ARunCutOffOnTheCommandLineContinuesOnTheRunPageWithItsPlantAndIntegralAction) {
    // The same run twice on the command line: left alone, and cut off with SIGTERM after part 40; the Run page
    // continues the cut one from its stored request. The simulated lathe depends only on the part number and
    // the corrections the parts received, so both store the same diameters when the resumed run keeps the
    // plant gain 0.7 and the integral action (1e-12 mm: the stored controller state's rounding).
    const QStringList run{QStringLiteral("--preset"),     QStringLiteral("paper-2012"),
                          QStringLiteral("--delay"),      QStringLiteral("2"),
                          QStringLiteral("--parts"),      QStringLiteral("150"),
                          QStringLiteral("--warmup"),     QStringLiteral("0"),
                          QStringLiteral("--seed"),       QStringLiteral("5"),
                          QStringLiteral("--plant-gain"), QStringLiteral("0.7"),
                          QStringLiteral("--integral"),   QStringLiteral("on")};
    const QString whole = dir.filePath(QStringLiteral("whole.sqlite"));
    QProcess left;
    left.start(QStringLiteral(TRUETURN_EXE),
               QStringList{QStringLiteral("simulate")} + run + QStringList{QStringLiteral("--db"), whole});
    ASSERT_TRUE(left.waitForFinished(-1));
    ASSERT_EQ(left.exitCode(), 0) << left.readAllStandardError().toStdString();
    ASSERT_EQ(tt::test::interruptedSimulate(QStringLiteral(TRUETURN_EXE),
                                            run + QStringList{QStringLiteral("--db"), context.databasePath,
                                                              QStringLiteral("--speed"), QStringLiteral("18000")},
                                            40),
              130);

    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    auto* speed = window.findChild<QComboBox*>(QStringLiteral("speedCombo"));
    speed->setCurrentIndex(speed->count() - 1);  // the fastest pace
    prompt.answers.push_back(Prompt::Answer::Yes);
    ASSERT_TRUE(offerInterruptedRun(context, window));
    ASSERT_TRUE(waitFor([&] { return context.data().history()->runs().front().status == "complete"; }, 300000))
        << core::describe(page->session().snapshot().status);
    const std::vector<double> a = tt::test::storedDiameters(whole);
    const std::vector<double> b = tt::test::storedDiameters(context.databasePath);
    ASSERT_EQ(a.size(), 150u * 5u);
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_NEAR(a[i], b[i], 1e-12) << "reading " << i << " (part " << i / 5 + 1 << ")";
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
            const std::optional<runtime::InterruptedRun> run = findInterruptedRun(context);
            return run && run->point.lastPartNumber >= 5;
        },
        tt::test::kPatientWaitMs));
    simulate.terminate();
    ASSERT_TRUE(simulate.waitForFinished(tt::test::kPatientWaitMs));
    EXPECT_EQ(simulate.exitCode(), 130) << simulate.readAllStandardError().toStdString();

    const std::optional<runtime::InterruptedRun> found = findInterruptedRun(context);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->request.endPart, std::optional<std::int64_t>(400)) << "warm-up 0 + 400 parts";
    EXPECT_EQ(found->request.seed, 3u);
    const qint64 runId = found->point.run.runId;
    const qint64 next = found->nextPart();
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    std::set<qint64> startedParts;
    QObject::connect(&page->session(), &runtime::RunSession::loopEvent, &window, [&](const core::LoopEvent& e) {
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
