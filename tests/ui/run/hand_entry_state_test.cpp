// Hand entry at the default x360 speed (issue 17, item 9): the run waits for the person without a time
// limit, and at every moment the header's loop badge, the status bar and the alarms agree with the loop's
// own state: no "Paused" alarm or badge while the loop runs and waits, "Paused" when the operator pauses,
// "Idle" after Stop.
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTest>

#include "support/terminal_window.h"
#include "tests/support/patient_wait.h"
#include "ui/pages/run_page.h"
#include "runtime/run/run_session.h"

namespace tt::ui {
namespace {

using HandEntryState = test::TerminalWindowTest;

AppState::Loop expectedLoop(core::LoopState s) {
    switch (s) {
        case core::LoopState::Running:
            return AppState::Loop::Running;
        case core::LoopState::Paused:
            return AppState::Loop::Paused;
        case core::LoopState::Fault:
            return AppState::Loop::Fault;
        case core::LoopState::Idle:
            break;
    }
    return AppState::Loop::Idle;
}

int pausedAlarms(const QListWidget* alarms) {
    int n = 0;
    for (int i = 0; i < alarms->count(); ++i)
        if (alarms->item(i)->text().contains(QStringLiteral("aused"))) ++n;
    return n;
}

TEST_F(HandEntryState, TheHeaderAndTheAlarmsFollowTheLoopWhileItWaitsForThePerson) {
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* page = qobject_cast<RunPage*>(window->page(PageId::Run));
    ASSERT_NE(page, nullptr);
    auto* badge = window->findChild<QLabel*>(QStringLiteral("LoopBadge"));
    auto* status = window->findChild<QLabel*>(QStringLiteral("statusLoop"));
    ASSERT_TRUE(badge && status);
    ASSERT_EQ(window->findChild<QComboBox*>(QStringLiteral("speedCombo"))->currentIndex(), 2) << "x360 by default";
    window->findChild<QCheckBox*>(QStringLiteral("manualEntryCheck"))->setChecked(true);
    window->findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return page->session().snapshot().awaitingPart.has_value(); }, tt::test::kPatientWaitMs));

    // 6 s of wall time = 36 min at x360, ten times the old 3 s time-out: sampled every 20 ms.
    QStringList disagreements;
    auto sample = [&](const char* when) {
        const runtime::LoopSnapshot s = page->session().snapshot();
        QApplication::processEvents();  // the snapshot's signal reaches the page
        const runtime::LoopSnapshot now = page->session().snapshot();
        if (now.state != s.state) return;  // changed between the two reads: sample again
        const AppState::Loop loop = expectedLoop(now.state);
        const QString name = AppState::loopName(loop);
        if (state.loop() != loop) disagreements << QStringLiteral("%1: application state differs").arg(when);
        if (badge->text() != QStringLiteral("Loop: %1").arg(name))
            disagreements << QStringLiteral("%1: badge '%2' while the loop is %3").arg(when, badge->text(), name);
        if (!status->text().startsWith(QStringLiteral("Loop: %1").arg(name)))
            disagreements << QStringLiteral("%1: status '%2' while the loop is %3").arg(when, status->text(), name);
    };
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 6000) {
        sample("waiting");
        QTest::qWait(20);
    }
    EXPECT_EQ(page->session().snapshot().state, core::LoopState::Running) << "waits; no time-out";
    EXPECT_TRUE(page->session().snapshot().awaitingPart.has_value());
    EXPECT_EQ(pausedAlarms(page->alarms()), 0) << "no 'Paused' alarm while the loop waits for the person";

    window->findChild<QPushButton*>(QStringLiteral("pauseButton"))->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Paused; },
                                tt::test::kPatientWaitMs));
    for (int i = 0; i < 20; ++i) {
        sample("paused");
        QTest::qWait(20);
    }
    EXPECT_EQ(badge->text(), QStringLiteral("Loop: Paused"));
    window->findChild<QPushButton*>(QStringLiteral("pauseButton"))->click();  // continue
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Running; },
                                tt::test::kPatientWaitMs));
    sample("continued");
    window->findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; },
                                tt::test::kPatientWaitMs));
    QApplication::processEvents();
    sample("stopped");
    EXPECT_EQ(badge->text(), QStringLiteral("Loop: Idle"));
    EXPECT_TRUE(disagreements.isEmpty()) << disagreements.mid(0, 10).join(QLatin1Char('\n')).toStdString();
}

}  // namespace
}  // namespace tt::ui
