#pragma once

#include <QCoreApplication>

#include "devices/api/device_plugin.h"

namespace tt::devices::linuxcnc {

/// Factory of LinuxCNC devices (LinuxCncOutputDevice, kind CorrectionOutput). Exported by the Qt plugin in
/// linuxcnc_plugin.h. The "LinuxCNC lathe" machine needs the device's settings, so it is offered for each
/// configured LinuxCNC device (deviceMachines: linuxCncLatheOffer, linuxcnc_lathe_offer.h), not by shaftMachines().
class LinuxCncFactory : public DevicePlugin {
public:
    QString pluginId() const override { return QStringLiteral("linuxcnc"); }
    QString displayName() const override {
        return QCoreApplication::translate("LinuxCnc", "LinuxCNC remote shell (TCP)");
    }
    QList<DeviceKind> kinds() const override { return {DeviceKind::CorrectionOutput}; }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    QList<SettingIssue> validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
    /// The LinuxCNC lathe of the device: its part program written into the folder of the device's "Part program"
    /// setting when one is set (a folder LinuxCNC reads under the same path), else into deviceProgramFolder().
    QList<ShaftMachineOffer> deviceMachines(DeviceKind kind, const QVariantMap& settings) const override;
};

/// The folder of this computer the LinuxCNC lathe writes its part program to when the device names none (LinuxCNC
/// running on this computer): "trueturn-linuxcnc" in the temporary folder, made when missing.
QString deviceProgramFolder();

}  // namespace tt::devices::linuxcnc
