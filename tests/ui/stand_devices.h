#pragma once

// The built-in simulator's probe mandrel and drive read-out on their calibration stands, in a
// device manager whose clock the test steps by hand (core::ManualClock), so the devices' ticks see
// exactly the simulated time the test gives them. Header-only.
#include <QString>
#include <QTest>

#include "core/loop/loop_clock.h"
#include "devices/api/device_manager.h"

namespace tt::ui::test {

class StandDevices {
public:
    /// Adds and opens the two devices under the names given.
    StandDevices(const QString& probeName, const QString& driveName) {
        probeId = manager.addDevice(QStringLiteral("simulator"), devices::DeviceKind::Probe, probeName, {});
        driveId = manager.addDevice(QStringLiteral("simulator"), devices::DeviceKind::DriveCurrent, driveName, {});
        manager.openAll();
    }
    /// Moves simulated time on by `seconds` in 50 ms steps, letting the devices' timers tick. On a loaded
    /// machine a device's timer ticks less often than every step, so the tests' waits on a capture or a
    /// measurement are capped at generous amounts of simulated time (they end as soon as it is done).
    void step(double seconds) {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.05) {
            clock.advanceBy(0.05);
            QTest::qWait(12);
        }
    }
    /// Steps until the mandrel has said what it is (its 16-bit ADC) and the drive answers (at most
    /// 10 s of simulated time); whether they did.
    bool waitReady() {
        for (int i = 0; i < 200 && !ready(); ++i)
            step(0.05);
        return ready();
    }
    devices::Device& probe() { return *manager.device(probeId); }
    devices::Device& drive() { return *manager.device(driveId); }

    core::ManualClock clock;
    devices::DeviceManager manager{&clock};
    QString probeId;
    QString driveId;

private:
    bool ready() {
        const auto info = probe().tableUploadTarget()->mandrelInfo();
        return probe().health().ready() && drive().health().ready() && info && info->adcBits;
    }
};

}  // namespace tt::ui::test
