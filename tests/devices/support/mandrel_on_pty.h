#pragma once

// The emulated probe mandrel (devices/simulator/mandrel_emulator.h) at the far end of a real
// pseudo-terminal pair: it answers the device's commands as they arrive and streams samples in
// real time. Header-only; used by the probe-mandrel plugin tests and the UI tests.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include "devices/simulator/mandrel_emulator.h"
#include "tests/devices/support/pty_pair.h"

namespace tt::devices::test {

class MandrelOnPty {
public:
    /// `protocol` of the emulated firmware (2, or 1 for the first protocol).
    explicit MandrelOnPty(const QString& name, int protocol = probe::kProtocolVersion) : pty(name), mandrel(protocol) {
        pty.onBytes([this](const QByteArray& bytes) {
            pty.send(mandrel.receive(
                {reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())}));
        });
        clock.start();
        timer.setInterval(5);
        QObject::connect(&timer, &QTimer::timeout, [this] {
            const double t = clock.nsecsElapsed() * 1e-9;
            pty.send(mandrel.advance(t - last));
            last = t;
        });
        timer.start();
    }
    PtyPair pty;
    MandrelEmulator mandrel;
    QTimer timer;
    QElapsedTimer clock;
    double last = 0.0;
};

}  // namespace tt::devices::test
