#pragma once

#include "devices/api/device_plugin.h"

namespace tt::devices {

/// Factory of the Modbus devices (TCP or RTU): the drive-current readout (ModbusDriveDevice)
/// and the correction output to the CNC's PLC (ModbusOutputDevice). Exported by the Qt plugin
/// in modbus_plugin.h.
class ModbusFactory : public DevicePlugin {
public:
    QString pluginId() const override { return QStringLiteral("modbus"); }
    QString displayName() const override { return QStringLiteral("Modbus TCP/RTU"); }
    QList<DeviceKind> kinds() const override { return {DeviceKind::DriveCurrent, DeviceKind::CorrectionOutput}; }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    QList<SettingIssue> validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
};

}  // namespace tt::devices
