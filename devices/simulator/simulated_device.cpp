#include "devices/simulator/simulated_device.h"

#include <QCoreApplication>

namespace tt::devices {

SimulatedDevice::SimulatedDevice(DeviceKind kind, const DeviceContext& context, int tickMs)
    : DeviceBase(kind, context) {
    m_timer.setInterval(tickMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { heartbeat(); });
}

SimulatedDevice::~SimulatedDevice() {
    m_timer.stop();
}

QString SimulatedDevice::what() const {
    switch (kind()) {
        case DeviceKind::Gauge:
            return QCoreApplication::translate("Simulator", "the simulated gauge micrometer");
        case DeviceKind::Probe:
            return QCoreApplication::translate("Simulator", "the simulated probe mandrel");
        case DeviceKind::DriveCurrent:
            return QCoreApplication::translate("Simulator", "the simulated drive-current readout");
        case DeviceKind::CorrectionOutput:
            return QCoreApplication::translate("Simulator", "the simulated CNC output");
    }
    return {};
}

void SimulatedDevice::open() {
    m_open = true;
    m_wasUnplugged = false;
    setState(core::DeviceState::Connecting, QCoreApplication::translate("Simulator", "connecting to %1").arg(what()));
    m_timer.start();
    if (m_faults.disconnected) {
        heartbeat();
        return;
    }
    connected();
}

void SimulatedDevice::close() {
    m_open = false;
    m_timer.stop();
    setState(core::DeviceState::Disconnected);
    stateChecked();
}

double SimulatedDevice::noise() {
    if (!m_faults.noisy) return 0.0;
    m_random ^= m_random << 13;  // xorshift32 (Marsaglia 2003)
    m_random ^= m_random >> 17;
    m_random ^= m_random << 5;
    return m_faults.noiseAmplitude * (static_cast<double>(m_random) / 4294967295.0 * 2.0 - 1.0);
}

void SimulatedDevice::heartbeat() {
    if (!m_open) return;
    if (m_faults.disconnected) {
        m_wasUnplugged = true;
        setState(core::DeviceState::Error,
                 QCoreApplication::translate("Simulator", "%1 is unplugged (fault switch)").arg(what()));
        stateChecked();
        return;
    }
    if (m_wasUnplugged) {
        m_wasUnplugged = false;
        setState(core::DeviceState::Connecting,
                 QCoreApplication::translate("Simulator", "reconnecting to %1").arg(what()));
        connected();
    }
    tick();
    stateChecked();
}

}  // namespace tt::devices
