// Quitting the terminal (issue 17, items 7 and 10): in kiosk mode only when the engineer's gate
// (engineerMayQuit, ui/kiosk.h) allows it; with a run going or with unapplied edits only after the user
// confirmed; otherwise at once. Kiosk mode shows the window full screen without decorations (the
// `--kiosk` option itself: tests/app/dispatcher_test.cpp).
#include <QAction>
#include <QComboBox>
#include <QPushButton>
#include <QTest>

#include "support/terminal_window.h"
#include "tests/support/patient_wait.h"
#include "ui/kiosk.h"
#include "ui/pages/run_page.h"
#include "ui/pages/tools_page.h"
#include "runtime/run/run_session.h"
#include "ui/tools/tool_table_model.h"

namespace tt::ui {
namespace {

using QuitTerminal = test::TerminalWindowTest;

TEST_F(QuitTerminal, IdleWithoutEditsQuitsWithoutAQuestion) {
    auto window = openWindow();
    EXPECT_TRUE(window->close());
    EXPECT_TRUE(prompt.log.isEmpty()) << prompt.log.join(u", ").toStdString();
}

TEST_F(QuitTerminal, KioskModeQuitsOnlyWhenTheEngineerConfirms) {
    auto window = openWindow();
    window->setKiosk(true);
    prompt.answers = {Prompt::Answer::No};
    EXPECT_FALSE(window->close()) << "refused: the window stays";
    EXPECT_TRUE(window->isVisible());
    EXPECT_EQ(prompt.log.value(0), QStringLiteral("ask: Quit the terminal"));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("engineer"))) << prompt.lastText.toStdString();
    // The File > Quit menu goes through the same gate.
    prompt.answers = {Prompt::Answer::No};
    QAction* quit = nullptr;
    for (QAction* a : window->findChildren<QAction*>())
        if (a->text() == QStringLiteral("&Quit")) quit = a;
    ASSERT_NE(quit, nullptr);
    quit->trigger();
    EXPECT_TRUE(window->isVisible());
    EXPECT_EQ(prompt.log.size(), 2);
    prompt.answers = {Prompt::Answer::Yes};
    EXPECT_TRUE(window->close());
    EXPECT_FALSE(window->isVisible());
}

TEST_F(QuitTerminal, TheGateRefusesWithoutAPrompt) {
    EXPECT_FALSE(engineerMayQuit(nullptr, nullptr)) << "no one to ask: no quitting";
    prompt.answers = {Prompt::Answer::Yes};
    EXPECT_TRUE(engineerMayQuit(nullptr, &prompt));
}

TEST_F(QuitTerminal, KioskShowsFullScreenWithoutDecorations) {
    MainWindow window(context);
    showAsKiosk(&window);
    QApplication::processEvents();
    EXPECT_TRUE(window.isFullScreen());
    EXPECT_TRUE(window.windowFlags().testFlag(Qt::FramelessWindowHint));
}

TEST_F(QuitTerminal, ARunGoingAsksFirst) {
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* page = qobject_cast<RunPage*>(window->page(PageId::Run));
    ASSERT_NE(page, nullptr);
    window->findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Running; },
                                tt::test::kPatientWaitMs));
    prompt.answers = {Prompt::Answer::No};
    EXPECT_FALSE(window->close());
    EXPECT_EQ(prompt.log.value(0), QStringLiteral("ask: Quit TrueTurn?"));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("a run is going"))) << prompt.lastText.toStdString();
    EXPECT_EQ(page->session().snapshot().state, core::LoopState::Running) << "the run goes on";
    prompt.answers = {Prompt::Answer::Yes};
    EXPECT_TRUE(window->close());
}

TEST_F(QuitTerminal, UnappliedToolEditsAskFirst) {
    auto window = openWindow();
    window->showPage(PageId::Tools);
    auto* tools = qobject_cast<ToolsPage*>(window->page(PageId::Tools));
    ASSERT_NE(tools, nullptr);
    EXPECT_TRUE(tools->unappliedEdits().isEmpty());
    tools->addTool();  // a new tool in the table: pending until applied
    EXPECT_EQ(tools->toolModel()->pendingCount(), 1);
    EXPECT_FALSE(tools->unappliedEdits().isEmpty());
    prompt.answers = {Prompt::Answer::No};
    EXPECT_FALSE(window->close());
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("not applied"))) << prompt.lastText.toStdString();
    prompt.answers = {Prompt::Answer::Yes};
    EXPECT_TRUE(window->close());
}

}  // namespace
}  // namespace tt::ui
