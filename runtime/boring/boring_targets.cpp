#include "runtime/boring/boring_targets.h"

#include <QCoreApplication>
#include <stdexcept>

#include "core/run/boring_simulation.h"
#include "runtime/devices/device_hub.h"

namespace tt::runtime {

namespace {

BoringTarget ownPass(DeviceHub* hub) {
    BoringTarget t;
    t.key = QStringLiteral("station");
    t.name = QCoreApplication::translate("tt::runtime::BoringTargets", "Station's PLC");
    t.can = {true, true, true, false, false};
    t.prepare = [hub](const BoringSource& source, core::BoringRunChoices& choices, const core::BoringScenario& scenario,
                      double) -> PreparedStation {
        core::BoringScenario pass = scenario;
        pass.plcCycleS = choices.plcCycleS;
        choices.plane = 0;           // the pass's mandrel is calibrated with plane 1 along X
        choices.heldOffsetMm = 0.0;  // a new pass starts with the offset at 0
        try {
            return {hub->beginBoringPass(source.deviceId, pass), [] { return std::optional<double>(); }};
        } catch (const std::exception&) {
            throw std::invalid_argument(
                QCoreApplication::translate(
                    "tt::runtime::BoringTargets",
                    "The simulated pass cannot begin: its scenario or its mandrel's calibration is refused.")
                    .toStdString());
        }
    };
    return t;
}

BoringTarget cncOutput(DeviceHub* hub, const DeviceView& output) {
    BoringTarget t;
    t.key = QStringLiteral("dev:%1").arg(output.id);
    t.name = output.name;
    t.can.holdsOffset = true;
    t.prepare = [hub, id = output.id](const BoringSource& source, core::BoringRunChoices& choices,
                                      const core::BoringScenario&, double heldOffsetMm) -> PreparedStation {
        const DeviceView* v = hub->view(id);
        if (!v || v->kind != devices::DeviceKind::CorrectionOutput)
            throw std::invalid_argument(
                QCoreApplication::translate("tt::runtime::BoringTargets", "The chosen CNC output is gone.")
                    .toStdString());
        choices.heldOffsetMm = heldOffsetMm;
        std::shared_ptr<core::RelayedBoringStation> station =
            hub->connectBoring(source.deviceId, source.method, id, choices.plcCycleS);
        if (!station)
            throw std::invalid_argument(
                QCoreApplication::translate("tt::runtime::BoringTargets", "No devices are configured.").toStdString());
        return {station, [hub, station] {
                    hub->disconnectBoring();
                    return station->outputRelay().confirmedOffsetMm();
                }};
    };
    return t;
}

}  // namespace

QList<BoringTarget> boringTargets(DeviceHub* hub, const QString& sourceId, bool scenarioUsable) {
    QList<BoringTarget> targets;
    if (!hub) return targets;
    const DeviceView* source = hub->view(sourceId);
    if (source && source->runsBoringPass && scenarioUsable) targets << ownPass(hub);
    for (const QString& id : hub->devicesOfKind(devices::DeviceKind::CorrectionOutput))
        if (const DeviceView* v = hub->view(id)) targets << cncOutput(hub, *v);
    return targets;
}

}  // namespace tt::runtime
