#include "runtime/devices/boring_link.h"

#include <QMetaObject>
#include <algorithm>

#include "devices/api/device_manager.h"

namespace tt::runtime {

namespace {

constexpr int kPumpMs = 5;
/// An offset the GUI thread has not written for this long (or three PLC cycles, if longer) makes
/// the compensation hold: the CNC never falls further behind the compensation than that.
constexpr double kMinOffsetWaitS = 0.05;

core::DeviceHealth gone() {
    return {core::DeviceState::Disconnected, {}};
}

/// Passes what the source `port` took (null: the device is gone) into its relay, with its health.
template <class Port, class Relay>
void pass(Port* port, Relay& relay) {
    if (port)
        while (const auto sample = port->takeSample())
            relay.deliver(*sample);
    relay.publishHealth(port ? port->health() : gone());
}

}  // namespace

BoringLink::BoringLink(devices::DeviceManager* manager, QObject* parent) : QObject(parent), m_manager(manager) {
    m_timer.setInterval(kPumpMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &BoringLink::pump);
    if (m_manager) {
        connect(m_manager, &devices::DeviceManager::deviceChanged, this, &BoringLink::pump);
        connect(m_manager, &devices::DeviceManager::devicesChanged, this, &BoringLink::pump);
    }
}

BoringLink::~BoringLink() {
    disconnectDevices();
}

std::shared_ptr<core::RelayedBoringStation> BoringLink::connectDevices(const QString& sourceId,
                                                                       core::BoringMethod method,
                                                                       const QString& outputId, double plcCycleS) {
    disconnectDevices();
    const core::Clock* clock = m_manager ? &m_manager->clock() : nullptr;
    if (!clock) return nullptr;
    auto station = std::make_shared<core::RelayedBoringStation>(*clock, method == core::BoringMethod::Current,
                                                                method == core::BoringMethod::Probe,
                                                                std::max(kMinOffsetWaitS, 3.0 * plcCycleS));
    if (devices::Device* source = m_manager->device(sourceId)) {
        if (core::DriveCurrentReadout* r = source->driveCurrentReadout())
            while (r->takeSample()) {
            }
        if (core::DeflectionProbe* p = source->deflectionProbe())
            while (p->takeSample()) {
            }
    }
    m_sourceId = sourceId;
    m_outputId = outputId;
    m_method = method;
    m_writes.clear();
    // Woken from the compensation's thread (under the relay's lock) when an offset waits.
    station->outputRelay().setRequestListener(
        [this] { QMetaObject::invokeMethod(this, &BoringLink::pump, Qt::QueuedConnection); });
    m_station = station;
    pump();
    m_timer.start();
    return station;
}

void BoringLink::disconnectDevices() {
    m_timer.stop();
    if (!m_station) return;
    m_station->outputRelay().close();
    if (core::DriveRelay* r = m_station->driveRelay()) r->publishHealth(gone());
    if (core::ProbeRelay* p = m_station->probeRelay()) p->publishHealth(gone());
    m_station.reset();
}

void BoringLink::pump() {
    if (!m_station) return;
    pumpSource();
    pumpOutput();
}

void BoringLink::pumpSource() {
    devices::Device* source = m_manager ? m_manager->device(m_sourceId) : nullptr;
    if (core::DriveRelay* relay = m_station->driveRelay())
        pass(source ? source->driveCurrentReadout() : nullptr, *relay);
    if (core::ProbeRelay* relay = m_station->probeRelay()) pass(source ? source->deflectionProbe() : nullptr, *relay);
}

void BoringLink::pumpOutput() {
    devices::Device* device = m_manager ? m_manager->device(m_outputId) : nullptr;
    core::CorrectionOutput* output = device ? device->correctionOutput() : nullptr;
    core::OffsetRelay& relay = m_station->outputRelay();
    if (const std::optional<double> offset = relay.takePending()) {
        const core::OutputResult result = output ? output->sendDynamicOffset(*offset) : core::OutputResult{false, {}};
        relay.reply(*offset, result);
        m_writes.record(std::chrono::steady_clock::now());
    }
    relay.publishHealth(output ? output->health() : gone());
}

}  // namespace tt::runtime
