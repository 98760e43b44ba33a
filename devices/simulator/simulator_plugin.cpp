#include "devices/simulator/simulator_plugin.h"

#include "devices/simulator/simulated_drive.h"
#include "devices/simulator/simulated_gauge.h"
#include "devices/simulator/simulated_lathe_offer.h"
#include "devices/simulator/simulated_output.h"
#include "devices/simulator/simulated_probe.h"
#include "devices/simulator/simulator_settings.h"

namespace tt::devices {

SettingsSchema SimulatorPlugin::settingsSchema(DeviceKind kind) const {
    switch (kind) {
        case DeviceKind::Gauge:
            return simulatedGaugeSchema();
        case DeviceKind::Probe:
            return simulatedProbeSchema();
        case DeviceKind::DriveCurrent:
            return simulatedDriveSchema();
        case DeviceKind::CorrectionOutput:
            return simulatedOutputSchema();
    }
    return {};
}

std::unique_ptr<Device> SimulatorPlugin::create(DeviceKind kind, const QVariantMap& settings,
                                                const DeviceContext& context) {
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    switch (kind) {
        case DeviceKind::Gauge:
            return std::make_unique<SimulatedGauge>(values, context);
        case DeviceKind::Probe:
            return std::make_unique<SimulatedProbe>(values, context);
        case DeviceKind::DriveCurrent:
            return std::make_unique<SimulatedDrive>(values, context);
        case DeviceKind::CorrectionOutput:
            return std::make_unique<SimulatedOutput>(values, context);
    }
    throw std::invalid_argument("the simulator does not make this device kind");
}

QList<ShaftMachineOffer> SimulatorPlugin::shaftMachines() const {
    return {simulatedLatheOffer()};
}

}  // namespace tt::devices
