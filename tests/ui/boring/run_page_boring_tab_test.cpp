// The in-process compensation as the second tab of the Run page, in the 1280 × 800 main window the
// operator sees: the simulator drive's own boring pass compensating, readable from a metre.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/boring/boring_panel.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

TEST(RunPageBoringTab, TheSecondTabRunsTheSimulatorsOwnPassInTheMainWindow) {
    QSettings().remove(QStringLiteral("boringPanel"));
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    const QString drive = devices.addDevice(QStringLiteral("simulator"), devices::DeviceKind::DriveCurrent,
                                            QStringLiteral("Cross feed (simulator)"), {});
    devices.openAll();
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
    ASSERT_TRUE(panel->selectSource(QStringLiteral("dev:%1:current").arg(drive)));
    EXPECT_EQ(panel->outputBox()->currentData().toString(), QStringLiteral("station"));  // the drive's own pass
    panel->speedBox()->setCurrentIndex(panel->speedBox()->findData(50));
    ASSERT_TRUE(panel->start()) << panel->reason().toStdString();
    // 30 s of the pass: the tool 25 mm into the bore.
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->stats().cycles >= 1500; }, tt::test::kPatientWaitMs))
        << panel->stats().cycles;
    EXPECT_EQ(panel->headline(), QStringLiteral("Compensating"));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("boring_run_page_tab")));
    panel->stop();
}

}  // namespace
}  // namespace tt::ui
