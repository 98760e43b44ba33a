#pragma once

#include <QCoreApplication>

#include "devices/api/device_plugin.h"

namespace tt::devices {

/// Factory of serial gauge micrometers (see SerialGaugeDevice). The Qt plugin class in
/// gauge_serial_plugin.h exports it; tests use it directly.
class GaugeSerialFactory : public DevicePlugin {
public:
    QString pluginId() const override { return QStringLiteral("gauge-serial"); }
    QString displayName() const override { return QCoreApplication::translate("SerialGauge", "Serial data cable"); }
    QList<DeviceKind> kinds() const override { return {DeviceKind::Gauge}; }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    QList<SettingIssue> validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
};

}  // namespace tt::devices
