#pragma once

#include <QCoreApplication>

#include "devices/api/device_plugin.h"

namespace tt::devices::linuxcnc {

/// Factory of LinuxCNC devices (LinuxCncOutputDevice, kind CorrectionOutput). Exported by the Qt plugin in
/// linuxcnc_plugin.h. The "LinuxCNC lathe" machine needs the device's settings, so it is made with
/// linuxCncLatheOffer(settings) (linuxcnc_lathe_offer.h), not listed by shaftMachines().
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
};

}  // namespace tt::devices::linuxcnc
