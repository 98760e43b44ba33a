// The Devices page offscreen: adding a serial gauge micrometer through the generated form
// (an invalid port and baud first), testing the connection against an emulated micrometer on a
// real pseudo-terminal, applying, and the status bar following the device.
#include "ui/pages/devices_page.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTest>

#include "runtime/devices/device_hub.h"
#include "devices/simulator/micrometer_emulator.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/devices/support/pty_pair.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/devices/settings_form.h"
#include "ui/language.h"
#include "ui/main_window.h"

namespace tt::ui {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");

class DevicesPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        ASSERT_EQ(manager.loadPlugins(kBuildPlugins), 5)
            << manager.pluginErrors().join(QStringLiteral("; ")).toStdString();
        context.devices = &manager;
    }
    DevicesPage& page(MainWindow& window) {
        window.showPage(PageId::Devices);
        return *static_cast<DevicesPage*>(window.page(PageId::Devices));
    }
    template <typename T>
    T* child(QWidget& w, const QString& name) {
        T* found = w.findChild<T*>(name);
        EXPECT_NE(found, nullptr) << name.toStdString();
        return found;
    }
    static void typeInto(QWidget* editor, const QString& text) {
        QLineEdit* line = qobject_cast<QLineEdit*>(editor);
        if (!line) line = qobject_cast<QComboBox*>(editor)->lineEdit();
        line->selectAll();
        QTest::keyClick(line, Qt::Key_Backspace);
        QTest::keyClicks(line, text);
    }
    void chooseType(DevicesPage& p, const QString& pluginId, const QString& kind) {
        auto* types = child<QComboBox>(p, QStringLiteral("newDeviceType"));
        const int index = types->findData(QStringList{pluginId, kind});
        ASSERT_GE(index, 0);
        types->setCurrentIndex(index);
        child<QPushButton>(p, QStringLiteral("addDevice"))->click();
    }

    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub manager;
    AppContext context{&prompt, &state, &language, QStringLiteral("/tmp/trueturn-test/history.sqlite")};
};

TEST_F(DevicesPageTest, AddsASerialGaugeThroughTheFormAndTestsItsConnection) {
    devices::test::PtyPair pty(QStringLiteral("ttyMICROMETER"));
    devices::MicrometerEmulator micrometer(devices::MicrometerEmulator::Format::Ascii);
    micrometer.setRequest("1\r");
    micrometer.setSource([] { return 26.812; });
    pty.onBytes([&](const QByteArray& bytes) {
        pty.send(micrometer.receive(
            {reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())}));
    });

    MainWindow window(context);
    window.show();
    DevicesPage& p = page(window);
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Idle);
    chooseType(p, QStringLiteral("gauge-serial"), QStringLiteral("gauge"));
    SettingsForm& form = p.form();

    // An invalid port and baud rate: marked, explained, and neither tested nor added.
    typeInto(form.editor(QStringLiteral("port")), QStringLiteral("/dev/ttyNOPE0"));
    typeInto(form.editor(QStringLiteral("baud")), QStringLiteral("9601"));
    EXPECT_TRUE(form.issueText(QStringLiteral("port")).contains(QStringLiteral("/dev/ttyNOPE0 does not exist")))
        << form.issueText(QStringLiteral("port")).toStdString();
    EXPECT_TRUE(
        form.issueText(QStringLiteral("baud")).startsWith(QStringLiteral("Baud rate: 9601 is not one of 1200")));
    EXPECT_TRUE(form.editor(QStringLiteral("baud"))->property("invalid").toBool());
    auto* apply = child<QPushButton>(p, QStringLiteral("applyDevice"));
    EXPECT_FALSE(apply->isEnabled());
    child<QPushButton>(p, QStringLiteral("testConnection"))->click();
    auto* result = child<QLabel>(p, QStringLiteral("TestResult"));
    EXPECT_EQ(result->text(), QStringLiteral("Not tested: correct the settings marked in red first."));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("devices_gauge_invalid")));

    // Corrected: the pty, 9600 baud, polled with the interface's request.
    typeInto(form.editor(QStringLiteral("port")), pty.portName());
    typeInto(form.editor(QStringLiteral("baud")), QStringLiteral("9600"));
    auto* mode = qobject_cast<QComboBox*>(form.editor(QStringLiteral("mode")));
    mode->setCurrentIndex(mode->findData(QStringLiteral("polled")));
    typeInto(form.editor(QStringLiteral("request")), QStringLiteral("1\\r"));
    EXPECT_TRUE(form.issueText(QStringLiteral("port")).isEmpty());
    EXPECT_TRUE(form.issueText(QStringLiteral("baud")).isEmpty());
    typeInto(child<QLineEdit>(p, QStringLiteral("deviceName")), QStringLiteral("Micrometer at the lathe"));
    EXPECT_TRUE(apply->isEnabled());
    child<QPushButton>(p, QStringLiteral("testConnection"))->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return result->text().startsWith(QStringLiteral("Connected")); },
                                tt::test::kPatientWaitMs))
        << result->text().toStdString();
    EXPECT_EQ(result->text(), QStringLiteral("Connected — 26.812 mm"));
    EXPECT_EQ(micrometer.readingsSent(), 1);

    // Added: opened, ready, persisted; the status bar says so.
    apply->click();
    ASSERT_EQ(manager.deviceIds().size(), 1);
    const QString id = manager.deviceIds().front();
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(id)->health.state == core::DeviceState::Ready; }, tt::test::kPatientWaitMs))
        << manager.view(id)->health.message;
    EXPECT_EQ(manager.view(id)->name, QStringLiteral("Micrometer at the lathe"));
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Ok);
    EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("statusDevices"))->text(), QStringLiteral("Devices: 1 ready"));
    manager.requestReading(id);
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(id)->liveValue == QStringLiteral("26.812 mm"); }, tt::test::kPatientWaitMs));
    // The page refreshes its counters twice a second.
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return child<QLabel>(p, QStringLiteral("LiveValue"))->text() == QStringLiteral("26.812 mm"); },
        tt::test::kPatientWaitMs))
        << child<QLabel>(p, QStringLiteral("LiveValue"))->text().toStdString();
    {
        QSettings settings;
        EXPECT_EQ(settings.value(QStringLiteral("devices/instances/size")).toInt(), 1);
        EXPECT_EQ(settings.value(QStringLiteral("devices/instances/1/plugin")).toString(),
                  QStringLiteral("gauge-serial"));
    }
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("devices_gauge_connected")));

    // Unplugged: the device, the list and the status bar show the error.
    pty.releaseSlave();
    pty.unplug();
    ASSERT_TRUE(QTest::qWaitFor([&] { return state.deviceTone() == AppState::Tone::Fault; }, tt::test::kPatientWaitMs));
    EXPECT_TRUE(state.deviceSummary().startsWith(QStringLiteral("Micrometer at the lathe: the gauge on")))
        << state.deviceSummary().toStdString();
    QTest::qWait(600);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("devices_gauge_unplugged")));
}

TEST_F(DevicesPageTest, SimulatorFaultSwitchesRevertAndRemove) {
    MainWindow window(context);
    window.show();
    DevicesPage& p = page(window);
    chooseType(p, QStringLiteral("simulator"), QStringLiteral("probe"));
    child<QPushButton>(p, QStringLiteral("applyDevice"))->click();
    ASSERT_EQ(manager.deviceIds().size(), 1);
    const QString probe = manager.deviceIds().front();
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(probe)->health.state == core::DeviceState::Ready; }, tt::test::kPatientWaitMs));

    // Unapplied edits are undone by Revert.
    QWidget* rate = p.form().editor(QStringLiteral("rateHz"));
    typeInto(rate, QStringLiteral("2000"));
    EXPECT_TRUE(p.form().issueText(QStringLiteral("rateHz")).contains(QStringLiteral("outside 1 to 1000 Hz")));
    child<QPushButton>(p, QStringLiteral("revertDevice"))->click();
    EXPECT_EQ(qobject_cast<QLineEdit*>(rate)->text(), QStringLiteral("200"));
    EXPECT_TRUE(p.form().issueText(QStringLiteral("rateHz")).isEmpty());

    // The unplug switch: error, shown in the status bar; released: ready again.
    QCheckBox* unplug = nullptr;
    for (QCheckBox* box : p.findChildren<QCheckBox*>())
        if (box->text() == QStringLiteral("Unplugged")) unplug = box;
    ASSERT_NE(unplug, nullptr);
    ASSERT_TRUE(unplug->isVisible());
    unplug->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return state.deviceTone() == AppState::Tone::Fault; }, tt::test::kPatientWaitMs));
    QTest::qWait(600);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("devices_simulator_unplugged")));
    unplug->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return state.deviceTone() == AppState::Tone::Ok; }, tt::test::kPatientWaitMs));

    // Remove asks first.
    prompt.answers.push_back(Prompt::Answer::No);
    child<QPushButton>(p, QStringLiteral("removeDevice"))->click();
    EXPECT_EQ(manager.deviceIds().size(), 1);
    prompt.answers.push_back(Prompt::Answer::Yes);
    child<QPushButton>(p, QStringLiteral("removeDevice"))->click();
    EXPECT_TRUE(manager.deviceIds().isEmpty());
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Idle);
    EXPECT_EQ(prompt.log.size(), 2);
}

TEST_F(DevicesPageTest, ATestReadingOfTheGaugeWaitsUntilTheRunIsStopped) {
    MainWindow window(context);
    window.show();
    DevicesPage& p = page(window);
    chooseType(p, QStringLiteral("simulator"), QStringLiteral("gauge"));
    child<QPushButton>(p, QStringLiteral("applyDevice"))->click();
    ASSERT_EQ(manager.deviceIds().size(), 1);
    const QString gauge = manager.deviceIds().front();
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(gauge)->health.state == core::DeviceState::Ready; }, tt::test::kPatientWaitMs));
    auto* result = child<QLabel>(p, QStringLiteral("TestResult"));
    auto* test = child<QPushButton>(p, QStringLiteral("testConnection"));

    // A run going (or paused): the test reading would be taken as a diameter, so nothing is asked.
    for (AppState::Loop loop : {AppState::Loop::Running, AppState::Loop::Paused}) {
        state.setLoop(loop, QString());
        const QString before = manager.view(gauge)->liveValue;
        test->click();
        EXPECT_TRUE(result->text().contains(QStringLiteral("Stop the run first"))) << result->text().toStdString();
        QTest::qWait(300);
        EXPECT_EQ(manager.view(gauge)->liveValue, before) << "the gauge was asked for a reading during a run";
        EXPECT_TRUE(test->isEnabled());
    }

    // Stopped: the test goes ahead and the gauge answers.
    state.setLoop(AppState::Loop::Idle, QString());
    test->click();
    EXPECT_FALSE(result->text().contains(QStringLiteral("Stop the run first")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return test->isEnabled(); }, tt::test::kPatientWaitMs));
    EXPECT_TRUE(result->text().startsWith(QStringLiteral("Connected"))) << result->text().toStdString();
}

}  // namespace
}  // namespace tt::ui
