// The Controller page's Apply reaches the Run page's running loop (issue 13 item 6): the new tuning takes
// over at a part boundary without a jump in the correction; with no run going it waits for the next Start.
// And the Run page's Start needs the "run the machine" permission (issue 17 item 12).
#include <gtest/gtest.h>

#include "config/controller_tuning_json.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QListWidget>
#include <QPushButton>
#include <QTest>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "config/loop_scenario.h"
#include "run_window.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "tests/support/patient_wait.h"
#include "ui/auth/user_session.h"
#include "ui/controller/controller_tuning.h"
#include "ui/controller/tuning_worker.h"
#include "ui/controller/weight_row.h"
#include "ui/pages/controller_page.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

using test::waitFor;

bool waitForNewest(ControllerPage& page) {
    return waitFor(
        [&] {
            const TuningResult* shown = page.shownResult();
            return shown && shown->generation == page.worker().latestGeneration();
        },
        tt::test::kPatientWaitMs);
}

class RunTuningTest : public test::RunWindowTest {
protected:
    void SetUp() override {
        context.tuning = &tuning;
        state.setOperatorName(QStringLiteral("Olga"));  // who the audit trail names
    }
    ControllerTuning tuning;
};

TEST_F(RunTuningTest, AppliedTuningTakesOverTheRunningLoopAtAPartWithoutAJump) {
    MainWindow window(context);
    RunPage* runPage = showRunPage(window);
    ASSERT_NE(runPage, nullptr);
    runtime::RunSession& session = runPage->session();
    std::map<qint64, std::vector<core::PointCorrectionRecord>> started;  // part -> its corrections
    QObject::connect(&session, &runtime::RunSession::loopEvent, &window, [&](const core::LoopEvent& e) {
        if (e.kind == core::LoopEvent::Kind::PartStarted) started[e.partNumber] = e.corrections;
    });
    qint64 takenAt = 0;
    QObject::connect(&session, &runtime::RunSession::tuningTaken, &window, [&](qint64 part) { takenAt = part; });

    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);  // x3600
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().partsFinished >= 6; }, tt::test::kPatientWaitMs))
        << core::describe(session.snapshot().status);

    window.showPage(PageId::Controller);
    auto* controller = qobject_cast<ControllerPage*>(window.page(PageId::Controller));
    ASSERT_NE(controller, nullptr);
    ASSERT_TRUE(waitForNewest(*controller));
    // A much lighter correction weight R2 at every point: a faster controller than the preset's.
    for (int i = 0; i < 5; ++i)
        controller->r2(i).field()->setValue(controller->appliedSetup().weights.R2(i, i) / 10.0);
    ASSERT_TRUE(waitForNewest(*controller));
    const qint64 partBeforeApply = session.snapshot().nextPart;
    prompt.answers.push_back(Prompt::Answer::Yes);
    window.findChild<QPushButton*>(QStringLiteral("applyTuning"))->click();
    ASSERT_TRUE(tuning.current().has_value()) << "Apply hands the tuning to the run";
    EXPECT_TRUE(controller->statusText().contains(QStringLiteral("running loop")))
        << controller->statusText().toStdString();

    ASSERT_TRUE(waitFor([&] { return takenAt > 0; }, tt::test::kPatientWaitMs)) << "the loop never took the new tuning";
    EXPECT_GE(takenAt, partBeforeApply) << "the switch is at a part not yet started when Apply was pressed";
    ASSERT_TRUE(waitFor([&] { return started.count(takenAt + 12) == 1; }, tt::test::kPatientWaitMs));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("controller_applied_to_running_loop")));

    // Bumpless (LoopEngine::replaceController): at the first part of the new controller the loop asks for
    // exactly the correction applied to the part before (to rounding, 1e-12 mm), and no part after moves
    // more than the loop's step limit (the preset's limits.max_step_mm, radial mm).
    const double maxStepMm = config::loadLoopScenario(QStringLiteral("paper-2012-group1"), 2)
                                 .loopConfig(true, std::nullopt)
                                 .limits.maxStepMm;
    ASSERT_TRUE(started.count(takenAt - 1) == 1);
    const auto& before = started[takenAt - 1];
    const auto& first = started[takenAt];
    ASSERT_EQ(first.size(), before.size());
    for (std::size_t i = 0; i < first.size(); ++i)
        EXPECT_NEAR(first[i].computedMm, before[i].appliedMm, 1e-12) << "point " << i;
    for (qint64 part = takenAt; part <= takenAt + 12; ++part)
        for (std::size_t i = 0; i < first.size(); ++i)
            EXPECT_LE(std::fabs(started[part][i].appliedMm - started[part - 1][i].appliedMm), maxStepMm + 1e-12)
                << "part " << part << " point " << i;
    bool said = false;
    for (int row = 0; row < runPage->alarms()->count(); ++row)
        said =
            said || runPage->alarms()->item(row)->text().contains(QStringLiteral("took over at part %1").arg(takenAt));
    EXPECT_TRUE(said);

    // Stopped: a second Apply waits for the next Start, which carries it.
    window.showPage(PageId::Run);
    window.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().state == core::LoopState::Idle; }, tt::test::kPatientWaitMs));
    window.showPage(PageId::Controller);
    controller->r1(0).field()->setValue(controller->appliedSetup().weights.R1(0, 0) * 2.0);
    ASSERT_TRUE(waitForNewest(*controller));
    prompt.answers.push_back(Prompt::Answer::Yes);
    window.findChild<QPushButton*>(QStringLiteral("applyTuning"))->click();
    EXPECT_TRUE(controller->statusText().contains(QStringLiteral("next Start")))
        << controller->statusText().toStdString();
    const runtime::RunRequest next = runPage->request();
    ASSERT_TRUE(next.tuning.has_value());
    const core::RunToRunSetup carried =
        config::tunedSetupFromJson(*next.tuning, runtime::scenarioOf(runtime::RunRequest{}).control);
    EXPECT_DOUBLE_EQ(carried.weights.R1(0, 0), controller->appliedSetup().weights.R1(0, 0));
}

TEST_F(RunTuningTest, AQualityUserCannotStartTheMachine) {
    UserSession users(&state);
    context.session = &users;
    context.access = &users.guard();
    users.logIn({"Vera", core::auth::Role::Quality}, 10);
    MainWindow window(context);
    RunPage* runPage = showRunPage(window);
    ASSERT_NE(runPage, nullptr);
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    QTest::qWait(300);
    EXPECT_EQ(runPage->session().snapshot().state, core::LoopState::Idle);
    EXPECT_FALSE(runPage->session().snapshot().runId.has_value()) << "nothing started";
    ASSERT_FALSE(prompt.log.isEmpty());
    EXPECT_EQ(prompt.log.back(), QStringLiteral("warn: The run cannot start"));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("Vera (quality)"))) << prompt.lastText.toStdString();
    EXPECT_TRUE(window.findChild<QPushButton*>(QStringLiteral("startButton"))->isEnabled());

    users.logIn({"Ivan", core::auth::Role::Operator}, 10);
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    EXPECT_TRUE(waitFor([&] { return runPage->session().snapshot().partsFinished >= 1; }, tt::test::kPatientWaitMs));
    window.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    EXPECT_TRUE(waitFor([&] { return runPage->session().snapshot().state == core::LoopState::Idle; },
                        tt::test::kPatientWaitMs));
}

}  // namespace
}  // namespace tt::ui
