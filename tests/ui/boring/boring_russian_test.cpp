// The Boring tab in Russian during a run whose source goes silent (issue 11, "Engine events as
// kinds"): the hold reason, the device's state and every other text of the tab are Russian; the
// engine sends kinds with data, the tab words them. Screenshot: screenshots/boring_tab_ru_silent.png.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "boring_tab.h"
#include "runtime/devices/device_hub.h"
#include "english_words.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "hub_faults.h"

namespace tt::ui {
namespace {

/// The tab of a 1280 × 800 main window in Russian, with the simulator's drive read-out and probe
/// mandrel (named in Russian, as the operator would) and their own simulated passes.
class BoringTabInRussian : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().remove(QStringLiteral("boringPanel"));
        ASSERT_TRUE(language.apply(QStringLiteral("ru")));
        drive = devices.addDevice(QStringLiteral("simulator"), devices::DeviceKind::DriveCurrent,
                                  QStringLiteral("Поперечная подача"), {});
        probe = devices.addDevice(QStringLiteral("simulator"), devices::DeviceKind::Probe,
                                  QStringLiteral("Оправка-датчик"), {});
        devices.openAll();
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }

    /// Runs the pass of `sourceKey` until the tool is 13 mm in, silences `device`, and returns the
    /// English the tab shows then (empty: none), after saving the screenshot `shot`.
    QStringList silenceDuringARun(const QString& sourceKey, const QString& device, const QString& reasonWords,
                                  const QString& shot) {
        MainWindow window(context);
        BoringPanel* panel = test::showBoringTab(window);
        EXPECT_NE(panel, nullptr);
        if (!panel || !panel->selectSource(sourceKey)) return {QStringLiteral("no source ") + sourceKey};
        panel->speedBox()->setCurrentIndex(panel->speedBox()->findData(50));
        EXPECT_TRUE(panel->start()) << panel->reason().toStdString();
        EXPECT_TRUE(QTest::qWaitFor([&] { return panel->stats().cycles >= 900; }, tt::test::kPatientWaitMs));
        EXPECT_EQ(panel->headline(), QStringLiteral("Компенсация")) << panel->reason().toStdString();
        // The source goes silent (its fault switch): the offset is held, and the tab says why, with
        // the device's own words underneath.
        test::setFault(devices, device, &devices::FaultSwitches::silent, true);
        EXPECT_TRUE(QTest::qWaitFor(
            [&] { return panel->headline() == QStringLiteral("Удержание") && !panel->detail().isEmpty(); },
            tt::test::kPatientWaitMs))
            << panel->reason().toStdString();
        QTest::qWait(150);  // the plots and numbers of the last cycles
        EXPECT_TRUE(panel->reason().contains(reasonWords)) << panel->reason().toStdString();
        EXPECT_TRUE(test::saveScreenshot(window, shot));
        QStringList english = test::englishIn(panel, {QStringLiteral("Boring bar D80 L800")});
        panel->stop();
        english << test::englishIn(panel, {QStringLiteral("Boring bar D80 L800")});
        test::setFault(devices, device, &devices::FaultSwitches::silent, false);
        return english;
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
    QString drive;
    QString probe;
};

TEST_F(BoringTabInRussian, ARunWhoseDriveReadOutGoesSilentShowsNoEnglish) {
    const QStringList english = silenceDuringARun(QStringLiteral("dev:%1:current").arg(drive), drive,
                                                  QStringLiteral("Датчик тока привода не отвечает или отключён"),
                                                  QStringLiteral("boring_tab_ru_silent"));
    EXPECT_TRUE(english.isEmpty()) << english.join(QStringLiteral("\n  ")).toStdString();
}

TEST_F(BoringTabInRussian, ARunWhoseMandrelGoesSilentShowsNoEnglish) {
    const QStringList english = silenceDuringARun(QStringLiteral("dev:%1:probe").arg(probe), probe,
                                                  QStringLiteral("Оправка-датчик не отвечает или отключена"),
                                                  QStringLiteral("boring_tab_ru_probe_silent"));
    EXPECT_TRUE(english.isEmpty()) << english.join(QStringLiteral("\n  ")).toStdString();
}

}  // namespace
}  // namespace tt::ui
