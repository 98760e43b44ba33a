// The in-process compensation as the second tab of the Run page, in the 1280 × 800 main window the
// operator sees: the simulated station compensating, readable from a metre.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>

#include "devices/api/device_manager.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/boring/boring_panel.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

TEST(RunPageBoringTab, TheSecondTabRunsTheSimulatedStationInTheMainWindow) {
    QSettings().remove(QStringLiteral("boringPanel"));
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    devices::DeviceManager devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Run);
    auto* run = dynamic_cast<RunPage*>(window.page(PageId::Run));
    ASSERT_NE(run, nullptr);
    QTabWidget* tabs = run->tabs();
    ASSERT_EQ(tabs->count(), 2);
    auto* panel = qobject_cast<BoringPanel*>(tabs->widget(1));
    ASSERT_NE(panel, nullptr);
    EXPECT_EQ(tabs->tabText(1), QStringLiteral("Boring bar (in-process)"));
    tabs->setCurrentIndex(1);
    QApplication::processEvents();
    // The panel fits the tab: no control is cut off at 1280 × 800.
    EXPECT_LE(panel->minimumSizeHint().width(), panel->width());
    EXPECT_LE(panel->minimumSizeHint().height(), panel->height());
    ASSERT_TRUE(panel->selectSource(QStringLiteral("sim:current")));
    ASSERT_TRUE(panel->start()) << panel->reason().toStdString();
    panel->runCycles(1500);  // 30 s of the pass: the tool 25 mm into the bore
    EXPECT_EQ(panel->headline(), QStringLiteral("Compensating"));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("boring_run_page_tab")));
    panel->stop();
}

}  // namespace
}  // namespace tt::ui
