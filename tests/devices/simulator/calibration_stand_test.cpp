// The built-in simulator's calibration stands (devices/api/calibration_stand.h): the probe
// mandrel's screw jack bends the bar and the mandrel reads it through its 16-bit bridge; the cross
// feed's hydraulic jack loads the tool holder and the read-out's registers carry the k_p stand's
// drive, from which the k_p procedure (core/calibration) recovers the true 150 N/A. Devices on a
// machine have no stand. Simulated time is stepped by hand (core::ManualClock), so the devices'
// ticks see exactly the time the test gives them.
#include <gtest/gtest.h>

#include <QTest>
#include <numeric>

#include "core/calibration/kp_procedure.h"
#include "core/control/dither_current_difference.h"
#include "core/loop/loop_clock.h"
#include "devices/api/simulated_instrument.h"
#include "devices/api/device_manager.h"
#include "devices/simulator/mandrel_emulator.h"
#include "devices/simulator/simulator_plugin.h"

namespace tt::devices {
namespace {

class CalibrationStandTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> make(DeviceKind kind, const QVariantMap& settings = {}) {
        auto d = plugin.create(kind, settings, DeviceContext{&clock});
        d->open();
        step(0.1);
        EXPECT_TRUE(d->health().ready()) << d->health().message;
        return d;
    }
    /// Moves simulated time on by `seconds` in 50 ms steps, letting the devices' timers tick.
    void step(double seconds) {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.05) {
            clock.advanceBy(0.05);
            QTest::qWait(12);
        }
    }

    core::ManualClock clock;
    SimulatorPlugin plugin;
};

TEST_F(CalibrationStandTest, TheMandrelsScrewJackBendsTheBarUntilReleased) {
    auto d = make(DeviceKind::Probe);
    CalibrationStand* stand = tt::devices::simulatedInstrument(*d)->calibrationStand();
    ASSERT_NE(stand, nullptr);
    EXPECT_TRUE(stand->bendsBar());
    EXPECT_FALSE(stand->appliesLoad());
    EXPECT_THROW(stand->applyLoadN(100.0), std::invalid_argument);
    EXPECT_THROW(stand->bendBar(2, 0.1), std::invalid_argument);
    EXPECT_THROW(stand->bendBar(0, 2.5), std::invalid_argument);  // beyond the jack's ±2 mm
    stand->bendBar(1, -0.1234);
    EXPECT_TRUE(stand->engaged());
    step(0.3);
    std::optional<core::ProbeSample> last;
    while (auto s = d->deflectionProbe()->takeSample())
        last = s;
    ASSERT_TRUE(last);
    // The emulated bridge's code for the jack's deflection; the other plane is unloaded.
    EXPECT_EQ(last->adcCode[1], MandrelEmulator::adcCode(-0.1234));
    EXPECT_EQ(last->adcCode[0], MandrelEmulator::adcCode(0.0));
    EXPECT_NEAR(last->deflectionMm[1], -0.1234, 1e-6);  // the delivery table is valid
    stand->release();
    EXPECT_FALSE(stand->engaged());
    step(0.3);
    while (auto s = d->deflectionProbe()->takeSample())
        last = s;
    EXPECT_NEAR(last->deflectionMm[1], -0.005, 1e-6);  // the stand-alone deflection again (settings)
}

TEST_F(CalibrationStandTest, TheCrossFeedsHydraulicJackGivesTheTrueKpThroughTheRegisters) {
    auto d = make(DeviceKind::DriveCurrent);  // polled every 20 ms: the PLC cycle of the stand
    CalibrationStand* stand = tt::devices::simulatedInstrument(*d)->calibrationStand();
    ASSERT_NE(stand, nullptr);
    EXPECT_TRUE(stand->appliesLoad());
    EXPECT_FALSE(stand->bendsBar());
    EXPECT_THROW(stand->bendBar(0, 0.1), std::invalid_argument);
    EXPECT_THROW(stand->applyLoadN(25000.0), std::invalid_argument);
    core::KpCalibrationProcedure procedure(std::make_unique<core::DitherCurrentDifference>());
    for (double load : {0.0, 200.0, 400.0, 600.0}) {
        stand->applyLoadN(load);
        procedure.measure(load);
        for (int i = 0; i < 400 && procedure.measuring(); ++i) {
            step(0.05);
            procedure.pump(*d->driveCurrentReadout(), 0.05);
        }
        const auto events = procedure.takeEvents();
        ASSERT_EQ(events.size(), 1u);
        ASSERT_EQ(events[0].kind, core::KpEvent::Kind::LoadMeasured) << static_cast<int>(events[0].strokeProblem);
        EXPECT_GE(events[0].value.pairs, 10);
    }
    ASSERT_TRUE(procedure.next());
    ASSERT_TRUE(procedure.fitOutcome().fit);
    // The stand's drive has k_p 150 N/A (core::CrossFeedDriveConfig); the registers carry the
    // current in 0.01 A, the estimator's figure on this drive is within 3 % (tests/core).
    EXPECT_NEAR(procedure.fitOutcome().fit->kpNPerA, 150.0, 150.0 * 0.03);
    stand->release();
    EXPECT_FALSE(stand->engaged());
    step(0.2);
    std::optional<core::DriveSample> last;
    while (auto s = d->driveCurrentReadout()->takeSample())
        last = s;
    ASSERT_TRUE(last);
    EXPECT_NEAR(std::abs(last->currentA - 0.6), 2.0, 0.006);  // the stand-alone oscillation again
}

TEST(CalibrationStand, OnlyTheSimulatorsProbeAndDriveHaveOneUnlessSetOff) {
    SimulatorPlugin plugin;
    core::ManualClock clock;
    for (DeviceKind kind : allDeviceKinds()) {
        auto d = plugin.create(kind, {}, DeviceContext{&clock});
        const bool expected = kind == DeviceKind::Probe || kind == DeviceKind::DriveCurrent;
        EXPECT_EQ(tt::devices::simulatedInstrument(*d)->calibrationStand() != nullptr, expected) << kindKey(kind).toStdString();
    }
    // "On a calibration stand" off: a simulated machine, where the operator loads the bar.
    for (DeviceKind kind : {DeviceKind::Probe, DeviceKind::DriveCurrent})
        EXPECT_EQ(tt::devices::simulatedInstrument(*plugin.create(kind, {{QStringLiteral("stand"), false}}, DeviceContext{&clock}))->calibrationStand(),
                  nullptr);
}

}  // namespace
}  // namespace tt::devices
