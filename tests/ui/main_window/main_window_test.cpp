#include "ui/main_window.h"

#include <gtest/gtest.h>

#include <trueturn/version.h>
#include <QApplication>
#include <QLabel>
#include <QStatusBar>
#include <QToolButton>

#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"

namespace tt::ui {
namespace {

class MainWindowTest : public ::testing::Test {
protected:
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, QStringLiteral("/tmp/trueturn-test/history.sqlite"), &devices};
};

TEST_F(MainWindowTest, VisitsEveryPageByItsNavigationButtonAndGrabsIt) {
    MainWindow window(context);
    window.show();
    ASSERT_EQ(window.pages().size(), 10);
    for (Page* page : window.pages()) {
        auto* button = window.findChild<QToolButton*>(QStringLiteral("nav_") + pageKey(page->id()));
        ASSERT_NE(button, nullptr) << pageKey(page->id()).toStdString();
        button->click();
        QApplication::processEvents();
        EXPECT_EQ(window.currentPage(), page->id());
        EXPECT_FALSE(page->title().isEmpty());
        EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("PageTitle"))->text(), page->title());
        EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("page_") + pageKey(page->id())));
    }
}

TEST_F(MainWindowTest, AboutShowsTheVersion) {
    MainWindow window(context);
    window.showAbout();
    ASSERT_EQ(prompt.log.size(), 1);
    EXPECT_TRUE(prompt.lastText.contains(QString::fromLatin1(tt::kVersion)));
}

TEST_F(MainWindowTest, StatusBarFollowsLoopAndDeviceState) {
    MainWindow window(context);
    state.setLoop(AppState::Loop::Paused, QStringLiteral("gauge silent"));
    state.setDevices(AppState::Tone::Fault, QStringLiteral("gauge: no answer"));
    auto* loop = window.findChild<QLabel*>(QStringLiteral("statusLoop"));
    auto* devices = window.findChild<QLabel*>(QStringLiteral("statusDevices"));
    EXPECT_EQ(loop->text(), QStringLiteral("Loop: Paused — gauge silent"));
    EXPECT_EQ(devices->text(), QStringLiteral("Devices: gauge: no answer"));
    EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("LoopBadge"))->property("tone").toString(),
              QStringLiteral("warn"));
}

TEST_F(MainWindowTest, SwitchesToRussianAndBack) {
    MainWindow window(context);
    window.show();
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QApplication::processEvents();
    auto* settings = window.findChild<QToolButton*>(QStringLiteral("nav_settings"));
    EXPECT_EQ(settings->text(), QStringLiteral("Настройки"));
    window.showPage(PageId::Run);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("page_run_ru")));
    ASSERT_TRUE(language.apply(QStringLiteral("en")));
    QApplication::processEvents();
    EXPECT_EQ(settings->text(), QStringLiteral("Settings"));
}

TEST_F(MainWindowTest, UnknownLanguageKeepsTheCurrentOne) {
    EXPECT_FALSE(language.apply(QStringLiteral("xx")));
    EXPECT_EQ(language.current(), QStringLiteral("en"));
}

}  // namespace
}  // namespace tt::ui
