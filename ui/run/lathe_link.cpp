#include "ui/run/lathe_link.h"

#include <QMetaObject>
#include <type_traits>
#include <variant>

#include "devices/api/device_manager.h"

namespace tt::ui {

namespace {

constexpr int kPumpMs = 20;

QString stateWord(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return LatheLink::tr("ready");
        case core::DeviceState::Connecting:
            return LatheLink::tr("still connecting");
        case core::DeviceState::Disconnected:
            return LatheLink::tr("closed");
        case core::DeviceState::Error:
            return LatheLink::tr("in error");
    }
    return {};
}

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

QString LatheLink::startProblem(const QString& outputId, const QString& gaugeId) const {
    if (!m_manager || outputId.isEmpty())
        return tr(
            "No CNC output is chosen. Add a G-code file or Modbus correction output on the Devices page and "
            "choose it under CNC output.");
    const devices::DeviceEntry* output = m_manager->entry(outputId);
    if (!output || !output->device->correctionOutput())
        return tr("The CNC output chosen is no longer on the Devices page; choose another.");
    const core::DeviceHealth oh = output->device->health();
    if (!oh.ready())
        return tr("The CNC output “%1” is %2: %3. Check it on the Devices page.")
            .arg(output->name, stateWord(oh.state), QString::fromStdString(oh.message));
    if (gaugeId.isEmpty()) return {};
    const devices::DeviceEntry* gauge = m_manager->entry(gaugeId);
    if (!gauge || !gauge->device->diameterGauge())
        return tr("The gauge chosen is no longer on the Devices page; choose another or type the diameters by hand.");
    const core::DeviceHealth gh = gauge->device->health();
    if (!gh.ready())
        return tr("The gauge “%1” is %2: %3. Check it on the Devices page, or choose to type the diameters by hand.")
            .arg(gauge->name, stateWord(gh.state), QString::fromStdString(gh.message));
    return {};
}

std::shared_ptr<const LathePorts> LatheLink::connectDevices(const QString& outputId, const QString& gaugeId) {
    disconnectDevices(tr("a new run was started"));
    auto ports = std::make_shared<LathePorts>();
    std::optional<double> nominalMm;
    if (const devices::DeviceEntry* e = m_manager ? m_manager->entry(outputId) : nullptr) {
        ports->outputName = e->name;
        if (e->settings.contains(QStringLiteral("nominalDiameterMm")))
            nominalMm = e->settings.value(QStringLiteral("nominalDiameterMm")).toDouble();
    }
    ports->machine = std::make_shared<core::RelayedLathe>(nominalMm);
    if (const devices::DeviceEntry* e = m_manager ? m_manager->entry(gaugeId) : nullptr) {
        ports->gaugeName = e->name;
        if (core::DiameterGauge* g = e->device->diameterGauge())
            while (g->takeReading()) {
            }  // taken before this run: not its diameters
    } else {
        ports->machine->gaugeRelay().publishHealth(
            {core::DeviceState::Disconnected, "no gauge chosen: the diameters are typed by hand"});
    }
    m_outputId = outputId;
    m_gaugeId = ports->gaugeName.isEmpty() ? QString() : gaugeId;
    // Woken from the loop thread (under the relay's lock) when a write waits; after close() never again.
    ports->machine->outputRelay().setRequestListener(
        [this] { QMetaObject::invokeMethod(this, &LatheLink::pump, Qt::QueuedConnection); });
    m_ports = ports;
    pump();
    m_timer.start();
    return ports;
}

void LatheLink::disconnectDevices(const QString& reason) {
    m_timer.stop();
    if (!m_ports) return;
    m_ports->machine->outputRelay().close(reason.toStdString());
    m_ports->machine->gaugeRelay().publishHealth({core::DeviceState::Disconnected, reason.toStdString()});
    m_ports.reset();
    m_outputId.clear();
    m_gaugeId.clear();
}

std::optional<qint64> LatheLink::partOnMachine() const {
    if (!m_ports) return std::nullopt;
    return m_ports->machine->operatorCycle().partOnMachine();
}

std::optional<qint64> LatheLink::finishPart() {
    if (!m_ports) return std::nullopt;
    return m_ports->machine->operatorCycle().finishPart();
}

void LatheLink::requestReading() {
    if (devices::Device* d = device(m_gaugeId); d && d->diameterGauge()) d->diameterGauge()->requestReading();
    pump();
}

QString LatheLink::gaugeValue() const {
    const devices::Device* d = device(m_gaugeId);
    return d ? d->liveValue() : QString();
}

QString LatheLink::outputValue() const {
    const devices::Device* d = device(m_outputId);
    return d ? d->liveValue() : QString();
}

void LatheLink::pump() {
    if (!m_ports) return;
    pumpOutput();
    pumpGauge();
}

void LatheLink::pumpGauge() {
    if (m_gaugeId.isEmpty()) return;
    devices::Device* d = device(m_gaugeId);
    core::DiameterGauge* gauge = d ? d->diameterGauge() : nullptr;
    if (!gauge) {
        m_ports->machine->gaugeRelay().publishHealth(
            {core::DeviceState::Disconnected, gone(tr("gauge"), m_ports->gaugeName).toStdString()});
        return;
    }
    core::GaugeRelay& relay = m_ports->machine->gaugeRelay();
    for (int n = relay.takeRequests(); n > 0; --n)
        gauge->requestReading();
    while (const auto reading = gauge->takeReading())
        relay.deliver(reading->diameterMm);
    relay.publishHealth(gauge->health());
}

void LatheLink::pumpOutput() {
    devices::Device* d = device(m_outputId);
    core::CorrectionOutput* output = d ? d->correctionOutput() : nullptr;
    const std::string missing = gone(tr("CNC output"), m_ports->outputName).toStdString();
    core::CorrectionRelay& relay = m_ports->machine->outputRelay();
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

}  // namespace tt::ui
