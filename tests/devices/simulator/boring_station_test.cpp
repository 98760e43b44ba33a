// The simulator's drive read-out and probe mandrel are also a simulated boring station (issue 11):
// they offer the BoringTruth capability (no other device does), each pass is the station the
// compensation runs on, and the device's fault switches reach the pass (silent, unplugged) with
// the device's own message.
#include <gtest/gtest.h>

#include <QTest>

#include "core/run/boring_run.h"
#include "devices/api/simulated_instrument.h"
#include "devices/api/steady_clock.h"
#include "devices/simulator/simulator_plugin.h"
#include "tests/core/support/heavy_scenario.h"

namespace tt::devices {
namespace {

class SimulatedBoringStationTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> open(DeviceKind kind) {
        auto d = plugin.create(kind, {}, DeviceContext{&clock});
        d->open();
        EXPECT_TRUE(QTest::qWaitFor([&] { return d->health().ready(); }, 2000)) << d->health().message;
        return d;
    }

    SteadyClock clock;
    SimulatorPlugin plugin;
};

TEST_F(SimulatedBoringStationTest, OnlyTheDriveAndTheMandrelOfferAPass) {
    for (DeviceKind kind : allDeviceKinds()) {
        auto d = plugin.create(kind, {}, DeviceContext{&clock});
        EXPECT_EQ(tt::devices::simulatedInstrument(*d)->boringTruth() != nullptr, kind == DeviceKind::DriveCurrent || kind == DeviceKind::Probe);
    }
}

TEST_F(SimulatedBoringStationTest, ThePassOfTheDriveCompensatesAndFollowsItsFaultSwitches) {
    auto drive = open(DeviceKind::DriveCurrent);
    const core::BoringScenario s = core::test::heavyBoring();
    const std::shared_ptr<core::BoringStation> pass = tt::devices::simulatedInstrument(*drive)->boringTruth()->beginPass(s);
    ASSERT_NE(pass->driveReadout(), nullptr);
    EXPECT_TRUE(pass->runsAheadOfTime());
    const std::unique_ptr<core::BoringRun> run =
        core::buildBoringRun(core::boringChoices(s, core::BoringMethod::Current), *pass);
    for (int i = 0; i < 1500; ++i)  // 30 s: the tool 25.5 mm into the bore
        run->cycle();
    const core::BoringRunCycle compensating = run->cycle();
    EXPECT_FALSE(compensating.compensation->step.holding);
    ASSERT_TRUE(compensating.truth.has_value());
    ASSERT_TRUE(compensating.truth->uncompensatedErrorMm.has_value());
    // README (current with dither): the bore error falls by 87 %; here at one point of the bore.
    EXPECT_LT(std::abs(compensating.truth->diameterErrorMm), 0.2 * std::abs(*compensating.truth->uncompensatedErrorMm));

    // The drive's silent switch: after three missed polls the device is in error, and so is the
    // pass's read-out, with the device's words.
    tt::devices::simulatedInstrument(*drive)->faultSwitches().silent = true;
    ASSERT_TRUE(QTest::qWaitFor([&] { return drive->health().state == core::DeviceState::Error; }, 2000));
    QTest::qWait(50);
    const core::BoringRunCycle silent = run->cycle();
    EXPECT_TRUE(silent.compensation->step.holding);
    EXPECT_EQ(silent.compensation->reading.problem, core::ReadingProblem::SourceNotReady);
    EXPECT_EQ(silent.compensation->reading.sourceHealth.message, drive->health().message);
    tt::devices::simulatedInstrument(*drive)->faultSwitches().silent = false;
    ASSERT_TRUE(QTest::qWaitFor([&] { return drive->health().ready(); }, 2000));
    QTest::qWait(50);
    EXPECT_EQ(pass->driveReadout()->health().state, core::DeviceState::Ready);
    // Unplugged likewise; and a pass that begins while the device is down begins gated.
    tt::devices::simulatedInstrument(*drive)->faultSwitches().disconnected = true;
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return pass->driveReadout()->health().state == core::DeviceState::Error; }, 2000));
    const std::shared_ptr<core::BoringStation> another = tt::devices::simulatedInstrument(*drive)->boringTruth()->beginPass(s);
    EXPECT_EQ(another->driveReadout()->health().state, core::DeviceState::Error);
}

TEST_F(SimulatedBoringStationTest, ThePassOfTheMandrelIsCalibratedFirst) {
    auto probe = open(DeviceKind::Probe);
    const core::BoringScenario s = core::test::heavyBoring();
    const std::shared_ptr<core::BoringStation> pass = tt::devices::simulatedInstrument(*probe)->boringTruth()->beginPass(s);
    ASSERT_NE(pass->probe(), nullptr);
    const std::unique_ptr<core::BoringRun> run =
        core::buildBoringRun(core::boringChoices(s, core::BoringMethod::Probe), *pass);
    for (int i = 0; i < 500; ++i)
        run->cycle();
    // Linearised samples: the mandrel carries the table calibrated on the simulated stand.
    const core::BoringRunCycle c = run->cycle();
    EXPECT_EQ(c.compensation->reading.problem, core::ReadingProblem::None);
    ASSERT_TRUE(c.compensation->reading.deflectionMm.has_value());
}

}  // namespace
}  // namespace tt::devices
