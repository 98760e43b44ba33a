// The operator terminal's devices (ui/devices/terminal_devices.h), as app/gui.cpp makes them before the
// main window: a first start gets one built-in simulator instance per device kind, opened and saved; later
// starts restore what was saved (also an empty list: nothing is re-added); every page sees the same manager,
// and the device badge follows it.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QTest>
#include <ostream>

#include "runtime/devices/device_hub.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "runtime/devices/terminal_devices.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/devices_page.h"
#include "ui/pages/run_page.h"
#include "hub_faults.h"

// Readable QString values in failure messages.
inline void PrintTo(const QString& text, std::ostream* os) {
    *os << '"' << text.toStdString() << '"';
}

namespace tt::ui {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");

class TerminalDevicesTest : public ::testing::Test {
protected:
    void SetUp() override { QSettings().clear(); }
};

TEST_F(TerminalDevicesTest, AFirstStartGetsOneOpenSimulatorPerKindAndLaterStartsRestoreWhatWasSaved) {
    QStringList firstIds;
    {
        runtime::TerminalDevices devices(kBuildPlugins);
        EXPECT_TRUE(devices.firstStart());
        EXPECT_TRUE(devices.problems().isEmpty()) << devices.problems().join(QStringLiteral("; ")).toStdString();
        runtime::DeviceHub& m = devices.hub();
        ASSERT_EQ(m.deviceIds().size(), 4);
        for (devices::DeviceKind kind : devices::allDeviceKinds()) {
            const QStringList ofKind = m.devicesOfKind(kind);
            ASSERT_EQ(ofKind.size(), 1) << devices::kindKey(kind).toStdString();
            const QString id = ofKind.front();
            EXPECT_EQ(m.view(id)->pluginId, QStringLiteral("simulator"));
            EXPECT_TRUE(QTest::qWaitFor([&] { return m.view(id)->health.ready(); }, tt::test::kPatientWaitMs))
                << "opened: " << m.view(id)->health.message;
        }
        EXPECT_EQ(m.view(m.devicesOfKind(devices::DeviceKind::Gauge).front())->name,
                  QStringLiteral("Simulated gauge micrometer"));
        EXPECT_EQ(m.summary().text, QStringLiteral("4 ready"));
        firstIds = m.deviceIds();
        // Removing one is saved at once (no page involved).
        m.removeDevice(m.devicesOfKind(devices::DeviceKind::Probe).front());
    }
    {
        runtime::TerminalDevices devices(kBuildPlugins);
        EXPECT_FALSE(devices.firstStart());
        QStringList expected = firstIds;
        expected.removeAt(1);  // the probe
        EXPECT_EQ(devices.hub().deviceIds(), expected);
        for (const QString& id : devices.hub().deviceIds())
            EXPECT_TRUE(QTest::qWaitFor([&] { return devices.hub().view(id)->health.ready(); }, tt::test::kPatientWaitMs));
        for (const QString& id : devices.hub().deviceIds())
            devices.hub().removeDevice(id);
    }
    {
        runtime::TerminalDevices devices(kBuildPlugins);
        EXPECT_FALSE(devices.firstStart()) << "an empty list is a choice, not a first start";
        EXPECT_TRUE(devices.hub().deviceIds().isEmpty());
    }
}

TEST_F(TerminalDevicesTest, APluginFolderThatIsMissingIsReportedAndTheSimulatorStillWorks) {
    runtime::TerminalDevices devices(QStringLiteral("/nonexistent/trueturn/plugins"));
    ASSERT_EQ(devices.problems().size(), 1);
    EXPECT_TRUE(devices.problems().front().contains(QStringLiteral("does not exist")));
    EXPECT_EQ(devices.hub().deviceIds().size(), 4);
}

TEST_F(TerminalDevicesTest, EveryPageSeesTheSameDevicesAndTheBadgeFollowsThem) {
    runtime::TerminalDevices devices(kBuildPlugins);
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    AppContext context{&prompt, &state, &language, QStringLiteral("/tmp/trueturn-test/history.sqlite"),
                       &devices.hub()};
    MainWindow window(context);
    ASSERT_TRUE(QTest::qWaitFor([&] { return devices.hub().summary().text == QStringLiteral("4 ready"); }, tt::test::kPatientWaitMs));
    auto* devicesPage = static_cast<DevicesPage*>(window.page(PageId::Devices));
    EXPECT_EQ(&devicesPage->hub(), &devices.hub());
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Ok);
    EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("DeviceBadge"))->text(), QStringLiteral("Devices: ready"));
    EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("statusDevices"))->text(), QStringLiteral("Devices: 4 ready"));
    // The Run page (built before the Devices page) offers the same instances for the real lathe.
    auto* run = static_cast<RunPage*>(window.page(PageId::Run));
    auto* output = run->findChild<QComboBox*>(QStringLiteral("cncOutputCombo"));
    ASSERT_EQ(output->count(), 1);
    EXPECT_EQ(output->itemData(0).toString(),
              devices.hub().devicesOfKind(devices::DeviceKind::CorrectionOutput).front());
    EXPECT_EQ(output->itemText(0), QStringLiteral("Simulated CNC output — ready"));
    auto* gauge = run->findChild<QComboBox*>(QStringLiteral("gaugeCombo"));
    ASSERT_EQ(gauge->count(), 2);
    EXPECT_EQ(gauge->itemText(1), QStringLiteral("Typed in by hand"));
    // A device's trouble reaches the badge and the Run page's choice.
    const QString gaugeId = devices.hub().devicesOfKind(devices::DeviceKind::Gauge).front();
    test::setFault(devices.hub(), gaugeId, &devices::FaultSwitches::disconnected, true);
    devices.hub().open(gaugeId);
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Fault);
    EXPECT_EQ(gauge->itemText(0), QStringLiteral("Simulated gauge micrometer — error"));
}

}  // namespace
}  // namespace tt::ui
