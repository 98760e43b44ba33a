// The devices live in a thread of their own: the hub makes and commands them there, the GUI thread sees
// snapshots; the built-in simulator is found like any plugin (a static one), and a simulated instrument's
// capabilities come through its own interface.
#include "runtime/devices/device_hub.h"

#include <gtest/gtest.h>

#include <QTest>
#include <QThread>

#include "devices/api/simulated_instrument.h"

namespace tt::runtime {
namespace {

const QString kSimulator = QStringLiteral("simulator");

TEST(DeviceHub, TheSimulatorIsFoundLikeAnyPluginAndItsInstancesLiveInTheDeviceThread) {
    DeviceHub hub;
    ASSERT_NE(hub.plugin(kSimulator), nullptr) << "the static plugin is found";
    EXPECT_FALSE(hub.shaftMachineOffers().isEmpty());
    const QString id = hub.addDevice(kSimulator, devices::DeviceKind::Gauge, QStringLiteral("Gauge"), {});
    ASSERT_NE(hub.view(id), nullptr) << "the snapshot is there when addDevice returns";
    QThread* owner = nullptr;
    hub.withDevice(id, [&](devices::Device&) { owner = QThread::currentThread(); });
    EXPECT_EQ(owner, hub.deviceThread());
    EXPECT_NE(owner, QThread::currentThread());
    hub.openAll();
    ASSERT_TRUE(QTest::qWaitFor([&] { return hub.view(id)->health.ready(); }, 5000));
    EXPECT_EQ(hub.summary().tone, DeviceSummary::Tone::Ok);
}

TEST(DeviceHub, ASimulatedInstrumentOffersItsFaultSwitchesAndAMachineDeviceDoesNot) {
    DeviceHub hub;
    const QString probe = hub.addDevice(kSimulator, devices::DeviceKind::Probe, QStringLiteral("Probe"), {});
    hub.openAll();
    const DeviceView* v = hub.view(probe);
    ASSERT_TRUE(v->faults.has_value());
    EXPECT_TRUE(v->runsBoringPass);
    EXPECT_TRUE(v->standBendsBar);
    EXPECT_TRUE(v->uploadsTable);
    devices::FaultSwitches faults = *v->faults;
    faults.disconnected = true;
    hub.setFaults(probe, faults);
    EXPECT_TRUE(hub.view(probe)->faults->disconnected) << "the snapshot follows the command at once";
    ASSERT_TRUE(QTest::qWaitFor([&] { return hub.view(probe)->health.state == core::DeviceState::Error; }, 5000));
    EXPECT_EQ(hub.summary().tone, DeviceSummary::Tone::Fault);
    bool simulated = false;
    hub.withDevice(probe, [&](devices::Device& d) { simulated = devices::simulatedInstrument(d) != nullptr; });
    EXPECT_TRUE(simulated);
}

TEST(DeviceHub, ATrialInstanceTestsTypedSettingsAndGoesAway) {
    DeviceHub hub;
    const QString gauge = hub.addDevice(kSimulator, devices::DeviceKind::Gauge, QStringLiteral("Gauge"), {});
    hub.openAll();
    hub.startTrial(kSimulator, devices::DeviceKind::Gauge, {}, gauge);
    ASSERT_NE(hub.view(kTrialDeviceId), nullptr);
    EXPECT_EQ(hub.deviceIds(), QStringList{gauge}) << "the trial is no configured instance";
    hub.testConnection(kTrialDeviceId);
    ASSERT_TRUE(QTest::qWaitFor([&] { return hub.view(kTrialDeviceId)->health.ready(); }, 5000));
    hub.endTrial();
    EXPECT_EQ(hub.view(kTrialDeviceId), nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return hub.view(gauge)->health.ready(); }, 5000)) << "reopened";
    EXPECT_THROW(hub.startTrial(QStringLiteral("no-such-plugin"), devices::DeviceKind::Gauge, {}, {}),
                 std::invalid_argument);
}

TEST(DeviceHub, BadSettingsAreRefusedInTheCallersThread) {
    DeviceHub hub;
    EXPECT_THROW(
        hub.addDevice(kSimulator, devices::DeviceKind::Probe, QStringLiteral("P"), {{QStringLiteral("rateHz"), 5000}}),
        std::invalid_argument);
    EXPECT_TRUE(hub.deviceIds().isEmpty());
}

}  // namespace
}  // namespace tt::runtime
