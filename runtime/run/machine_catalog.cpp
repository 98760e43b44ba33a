#include "runtime/run/machine_catalog.h"

#include <QCoreApplication>
#include <stdexcept>

#include "runtime/devices/device_hub.h"

namespace tt::runtime {

namespace {

QString stateWord(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return QCoreApplication::translate("tt::runtime::MachineCatalog", "ready");
        case core::DeviceState::Connecting:
            return QCoreApplication::translate("tt::runtime::MachineCatalog", "still connecting");
        case core::DeviceState::Disconnected:
            return QCoreApplication::translate("tt::runtime::MachineCatalog", "closed");
        case core::DeviceState::Error:
            return QCoreApplication::translate("tt::runtime::MachineCatalog", "in error");
    }
    return {};
}

/// Why the lathe from devices cannot run with the CNC output and gauge of `request` now; empty when it can.
QString devicesProblem(const DeviceHub* hub, const RunRequest& request) {
    const DeviceView* output = hub && !request.cncOutput.isEmpty() ? hub->view(request.cncOutput) : nullptr;
    if (!hub || request.cncOutput.isEmpty())
        return QCoreApplication::translate(
            "tt::runtime::MachineCatalog",
            "No CNC output is chosen. Add a G-code file or Modbus correction output on the Devices page and "
            "choose it under CNC output.");
    if (!output || output->kind != devices::DeviceKind::CorrectionOutput)
        return QCoreApplication::translate("tt::runtime::MachineCatalog",
                                           "The CNC output chosen is no longer on the Devices page; choose another.");
    if (!output->health.ready())
        return QCoreApplication::translate("tt::runtime::MachineCatalog",
                                           "The CNC output “%1” is %2: %3. Check it on the Devices page.")
            .arg(output->name, stateWord(output->health.state), QString::fromStdString(output->health.message));
    if (request.gauge.isEmpty()) return {};
    const DeviceView* gauge = hub->view(request.gauge);
    if (!gauge || gauge->kind != devices::DeviceKind::Gauge)
        return QCoreApplication::translate(
            "tt::runtime::MachineCatalog",
            "The gauge chosen is no longer on the Devices page; choose another or type the diameters by hand.");
    if (!gauge->health.ready())
        return QCoreApplication::translate(
                   "tt::runtime::MachineCatalog",
                   "The gauge “%1” is %2: %3. Check it on the Devices page, or choose to type the diameters by hand.")
            .arg(gauge->name, stateWord(gauge->health.state), QString::fromStdString(gauge->health.message));
    return {};
}

/// A plugin's complete machine as an offer.
MachineOffer fromPlugin(const devices::ShaftMachineOffer& offer) {
    MachineOffer m;
    m.key = offer.key;
    m.name = offer.name;
    m.description = offer.description;
    m.can.adjustableSpeed = offer.adjustableSpeed;
    m.cnc = offer.cnc;
    m.cncMode = offer.cncMode;
    m.startProblem = [](const RunRequest&) { return QString(); };
    m.prepare = [make = offer.make](const RunRequest& request) -> MachineMaker {
        return [make, seed = request.seed](const core::ShaftScenario& scenario) {
            return std::shared_ptr<core::ShaftMachine>(make(scenario, seed));
        };
    };
    m.release = [](const QString&) {};
    return m;
}

}  // namespace

QString currentMachineKey(const QString& storedKey) {
    if (storedKey == QLatin1String("real") || storedKey == QLatin1String("real-lathe")) return kDevicesLatheKey;
    return storedKey;
}

MachineCatalog::MachineCatalog(DeviceHub* hub) : m_hub(hub) {}

MachineOffer MachineCatalog::devicesLathe() const {
    MachineOffer m;
    m.key = kDevicesLatheKey;
    m.name = QCoreApplication::translate("tt::runtime::MachineCatalog", "Real lathe (Devices page)");
    m.description = QCoreApplication::translate(
        "tt::runtime::MachineCatalog",
        "each part's corrections go to the CNC; you machine the part and press Part finished.");
    m.can.usesDevices = true;
    m.can.partsConfirmedByOperator = true;
    DeviceHub* hub = m_hub;
    m.startProblem = [hub](const RunRequest& request) { return devicesProblem(hub, request); };
    m.prepare = [hub](const RunRequest& request) -> MachineMaker {
        if (const QString problem = devicesProblem(hub, request); !problem.isEmpty())
            throw std::invalid_argument(problem.toStdString());
        std::shared_ptr<core::ShaftMachine> lathe = hub->connectLathe(request.cncOutput, request.gauge);
        return [lathe](const core::ShaftScenario&) { return lathe; };
    };
    m.release = [hub](const QString& reason) {
        if (hub) hub->disconnectLathe(reason);
    };
    return m;
}

QList<MachineOffer> MachineCatalog::offers() const {
    QList<MachineOffer> all;
    if (m_hub)
        for (const devices::ShaftMachineOffer& offer : m_hub->shaftMachineOffers())
            all << fromPlugin(offer);
    all << devicesLathe();
    return all;
}

std::optional<MachineOffer> MachineCatalog::find(const QString& key) const {
    for (const MachineOffer& offer : offers())
        if (offer.key == key) return offer;
    return std::nullopt;
}

}  // namespace tt::runtime
