// The window's header follows the Boring tab's compensation (issue 17, item 10): "Loop: Running" while it
// compensates on the simulated drive's own pass, with the tab's headline in the status bar, "Loop: Idle"
// after Stop; quitting meanwhile asks first like a shaft run.
#include <QComboBox>
#include <QLabel>
#include <QTabWidget>
#include <QTest>

#include "runtime/devices/device_hub.h"
#include "support/terminal_window.h"
#include "tests/support/patient_wait.h"
#include "ui/boring/boring_panel.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

using BoringHeader = test::TerminalWindowTest;

TEST_F(BoringHeader, TheHeaderSaysWhatTheCompensationDoes) {
    runtime::DeviceHub& manager = devices->hub();
    const QString drive = manager.devicesOfKind(devices::DeviceKind::DriveCurrent).value(0);
    ASSERT_FALSE(drive.isEmpty()) << "the first start's simulated drive read-out";
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* run = qobject_cast<RunPage*>(window->page(PageId::Run));
    ASSERT_NE(run, nullptr);
    auto* panel = qobject_cast<BoringPanel*>(run->tabs()->widget(1));
    ASSERT_NE(panel, nullptr);
    run->tabs()->setCurrentIndex(1);
    auto* badge = window->findChild<QLabel*>(QStringLiteral("LoopBadge"));
    auto* status = window->findChild<QLabel*>(QStringLiteral("statusLoop"));
    ASSERT_TRUE(badge && status);
    EXPECT_EQ(badge->text(), QStringLiteral("Loop: Idle"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(drive)->health.ready(); }, tt::test::kPatientWaitMs));
    ASSERT_TRUE(panel->selectSource(QStringLiteral("dev:%1:current").arg(drive)));
    panel->speedBox()->setCurrentIndex(panel->speedBox()->findData(50));
    ASSERT_TRUE(panel->start()) << panel->reason().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->stats().cycles >= 1500; }, tt::test::kPatientWaitMs))
        << panel->stats().cycles;
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return panel->headline() == QStringLiteral("Compensating"); }, tt::test::kPatientWaitMs));
    QApplication::processEvents();
    EXPECT_EQ(state.loop(), AppState::Loop::Running);
    EXPECT_EQ(badge->text(), QStringLiteral("Loop: Running"));
    EXPECT_TRUE(status->text().contains(QStringLiteral("boring bar: Compensating"))) << status->text().toStdString();
    prompt.answers = {Prompt::Answer::No};
    EXPECT_FALSE(window->close()) << "a compensation going: quitting asks first";
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("a run is going"))) << prompt.lastText.toStdString();
    panel->stop();
    QApplication::processEvents();
    EXPECT_EQ(state.loop(), AppState::Loop::Idle);
    EXPECT_EQ(badge->text(), QStringLiteral("Loop: Idle"));
}

}  // namespace
}  // namespace tt::ui
