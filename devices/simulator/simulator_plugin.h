#pragma once

#include <QCoreApplication>
#include <QObject>

#include "devices/api/device_plugin.h"

namespace tt::devices {

/// The built-in simulator: always available (compiled into trueturn_devices as a static Qt plugin,
/// registered by registerBuiltInSimulator() and found by DeviceManager like any plugin), it makes every device
/// kind, each a SimulatedInstrument with fault switches (silent, noisy, stuck value, malformed frame,
/// disconnect) and simulation inputs for the lathe simulator.
class SimulatorPlugin final : public QObject, public DevicePlugin {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)

public:
    QString pluginId() const override { return QStringLiteral("simulator"); }
    QString displayName() const override { return QCoreApplication::translate("Simulator", "Simulator"); }
    QList<DeviceKind> kinds() const override { return allDeviceKinds(); }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
    /// The simulated lathe (simulated_lathe_offer.h).
    QList<ShaftMachineOffer> shaftMachines() const override;
};

}  // namespace tt::devices
