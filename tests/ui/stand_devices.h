#pragma once

// The built-in simulator's probe mandrel and drive read-out on their calibration stands, in a
// device manager whose clock the test steps by hand (core::ManualClock), so the devices' ticks see
// exactly the simulated time the test gives them. Header-only.
#include <QString>
#include <QTest>

#include "core/loop/loop_clock.h"
#include "runtime/devices/device_hub.h"

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

    core::ManualClock clock;
    runtime::DeviceHub manager{&clock};
    QString probeId;
    QString driveId;

private:
    bool ready() {
        manager.sync();
        const runtime::DeviceView* probe = manager.view(probeId);
        const runtime::DeviceView* drive = manager.view(driveId);
        return probe && drive && probe->health.ready() && drive->health.ready() && probe->mandrel &&
               probe->mandrel->adcBits;
    }
};

}  // namespace tt::ui::test
