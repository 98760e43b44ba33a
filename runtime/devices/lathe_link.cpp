#include "runtime/devices/lathe_link.h"

#include <QMetaObject>
#include <optional>
#include <type_traits>
#include <variant>

#include "devices/api/device_manager.h"

namespace tt::runtime {

namespace {

QString gone(const QString& what, const QString& name) {
    return LatheLink::tr("the %1 “%2” is no longer on the Devices page").arg(what, name);
}

}  // namespace

LatheLink::LatheLink(devices::DeviceManager* manager, QObject* parent) : QObject(parent), m_manager(manager) {
    m_timer.setInterval(kPumpMs);
    connect(&m_timer, &QTimer::timeout, this, &LatheLink::pump);
    if (m_manager) {
        connect(m_manager, &devices::DeviceManager::deviceChanged, this, &LatheLink::pump);
        connect(m_manager, &devices::DeviceManager::devicesChanged, this, &LatheLink::pump);
    }
}

LatheLink::~LatheLink() {
    disconnectDevices(tr("the Run page was closed"));
}

devices::Device* LatheLink::device(const QString& id) const {
    return m_manager && !id.isEmpty() ? m_manager->device(id) : nullptr;
}

std::shared_ptr<core::RelayedLathe> LatheLink::connectDevices(const QString& outputId, const QString& gaugeId) {
    disconnectDevices(tr("a new run was started"));
    std::optional<double> nominalMm;
    m_outputName.clear();
    m_gaugeName.clear();
    if (const devices::DeviceEntry* e = m_manager ? m_manager->entry(outputId) : nullptr) {
        m_outputName = e->name;
        if (e->settings.contains(QStringLiteral("nominalDiameterMm")))
            nominalMm = e->settings.value(QStringLiteral("nominalDiameterMm")).toDouble();
    }
    auto lathe = std::make_shared<core::RelayedLathe>(nominalMm);
    if (const devices::DeviceEntry* e = m_manager ? m_manager->entry(gaugeId) : nullptr) {
        m_gaugeName = e->name;
        if (core::DiameterGauge* g = e->device->diameterGauge())
            while (g->takeReading()) {
            }  // taken before this run: not its diameters
    } else {
        lathe->gaugeRelay().publishHealth(
            {core::DeviceState::Disconnected, "no gauge chosen: the diameters are typed by hand"});
    }
    m_outputId = outputId;
    m_gaugeId = m_gaugeName.isEmpty() ? QString() : gaugeId;
    // Woken from the loop thread (under the relay's lock) when a write waits; after close() never again.
    lathe->outputRelay().setRequestListener(
        [this] { QMetaObject::invokeMethod(this, &LatheLink::pump, Qt::QueuedConnection); });
    m_lathe = lathe;
    pump();
    m_timer.start();
    return lathe;
}

void LatheLink::disconnectDevices(const QString& reason) {
    m_timer.stop();
    if (!m_lathe) return;
    m_lathe->outputRelay().close(reason.toStdString());
    m_lathe->gaugeRelay().publishHealth({core::DeviceState::Disconnected, reason.toStdString()});
    m_lathe.reset();
    m_outputId.clear();
    m_gaugeId.clear();
}

void LatheLink::pump() {
    if (!m_lathe) return;
    pumpOutput();
    pumpGauge();
}

void LatheLink::pumpGauge() {
    if (m_gaugeId.isEmpty()) return;
    devices::Device* d = device(m_gaugeId);
    core::DiameterGauge* gauge = d ? d->diameterGauge() : nullptr;
    if (!gauge) {
        m_lathe->gaugeRelay().publishHealth(
            {core::DeviceState::Disconnected, gone(tr("gauge"), m_gaugeName).toStdString()});
        return;
    }
    core::GaugeRelay& relay = m_lathe->gaugeRelay();
    for (int n = relay.takeRequests(); n > 0; --n)
        gauge->requestReading();
    while (const auto reading = gauge->takeReading())
        relay.deliver(reading->diameterMm);
    relay.publishHealth(gauge->health());
}

void LatheLink::pumpOutput() {
    devices::Device* d = device(m_outputId);
    core::CorrectionOutput* output = d ? d->correctionOutput() : nullptr;
    const std::string missing = gone(tr("CNC output"), m_outputName).toStdString();
    core::CorrectionRelay& relay = m_lathe->outputRelay();
    while (const auto request = relay.takeRequest()) {
        core::OutputResult result{false, missing};
        if (output)
            result = std::visit(
                [output](const auto& write) {
                    if constexpr (std::is_same_v<std::decay_t<decltype(write)>, core::PartCorrection>)
                        return output->sendPartCorrection(write);
                    else
                        return output->sendDynamicOffset(write);
                },
                request->write);
        relay.reply(request->id, result);
    }
    relay.publishHealth(output ? output->health() : core::DeviceHealth{core::DeviceState::Disconnected, missing});
}

}  // namespace tt::runtime
