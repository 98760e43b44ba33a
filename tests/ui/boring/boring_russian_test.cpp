// The Boring tab in Russian during a run whose source goes silent (issue 11, "Engine events as
// kinds"): the hold reason, the device's state and every other text of the tab are Russian; the
// engine sends kinds with data, the tab words them. Screenshot: screenshots/boring_tab_ru_silent.png.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "boring_tab.h"
#include "devices/api/device_manager.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"

namespace tt::ui {
namespace {

/// Texts `root` shows that hold an English word (two Latin letters in a row), each with where it is.
/// `data` are names the operator or the preset gave (a tool's name), not texts of the terminal.
QStringList englishIn(QWidget* root, const QStringList& data) {
    static const QRegularExpression latinWord(QStringLiteral("[A-Za-z]{2,}"));
    QStringList found;
    auto check = [&](const QWidget* w, QString text) {
        for (const QString& name : data)
            text.remove(name);
        if (text.contains(latinWord))
            found << QStringLiteral("\"%1\" in %2 '%3'")
                         .arg(text, QString::fromLatin1(w->metaObject()->className()), w->objectName());
    };
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(root)) continue;
        if (auto* label = qobject_cast<QLabel*>(w)) check(w, label->text());
        if (auto* button = qobject_cast<QAbstractButton*>(w)) check(w, button->text());
        if (auto* group = qobject_cast<QGroupBox*>(w)) check(w, group->title());
        if (auto* progress = qobject_cast<QProgressBar*>(w)) check(w, progress->text());
        if (auto* combo = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < combo->count(); ++i)
                check(w, combo->itemText(i));
    }
    return found;
}

TEST(BoringTabInRussian, ARunWhoseSourceGoesSilentShowsNoEnglish) {
    QSettings().remove(QStringLiteral("boringPanel"));
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    devices::DeviceManager devices;
    const QString drive = devices.addDevice(QStringLiteral("simulator"), devices::DeviceKind::DriveCurrent,
                                            QStringLiteral("Поперечная подача"), {});
    devices.openAll();
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
    MainWindow window(context);
    BoringPanel* panel = test::showBoringTab(window);
    ASSERT_NE(panel, nullptr);

    ASSERT_TRUE(panel->selectSource(QStringLiteral("dev:%1:current").arg(drive)));
    panel->speedBox()->setCurrentIndex(panel->speedBox()->findData(50));
    ASSERT_TRUE(panel->start()) << panel->reason().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel->stats().cycles >= 900; }, 20000));
    ASSERT_EQ(panel->headline(), QStringLiteral("Компенсация")) << panel->reason().toStdString();

    // The drive read-out goes silent (its fault switch): the offset is held, and the tab says why,
    // with the device's own words underneath.
    devices.device(drive)->faultSwitches()->silent = true;
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return panel->headline() == QStringLiteral("Удержание") && !panel->detail().isEmpty(); }, 5000))
        << panel->reason().toStdString();
    QTest::qWait(150);  // the plots and numbers of the last cycles
    EXPECT_TRUE(panel->reason().contains(QStringLiteral("Датчик тока привода не отвечает или отключён")))
        << panel->reason().toStdString();
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("boring_tab_ru_silent")));
    const QStringList english = englishIn(panel, {QStringLiteral("Boring bar D80 L800")});
    EXPECT_TRUE(english.isEmpty()) << english.join(QStringLiteral("\n  ")).toStdString();
    panel->stop();
    EXPECT_TRUE(englishIn(panel, {QStringLiteral("Boring bar D80 L800")}).isEmpty());
    ASSERT_TRUE(language.apply(QStringLiteral("en")));
}

}  // namespace
}  // namespace tt::ui
