#pragma once

#include <QCoreApplication>

#include "devices/api/device_plugin.h"

namespace tt::devices {

/// Factory of G-code file outputs (GCodeFileOutput). Exported by the Qt plugin in
/// gcode_output_plugin.h.
class GCodeOutputFactory : public DevicePlugin {
public:
    QString pluginId() const override { return QStringLiteral("cnc-gcode"); }
    QString displayName() const override { return QCoreApplication::translate("GCodeOutput", "G-code file"); }
    QList<DeviceKind> kinds() const override { return {DeviceKind::CorrectionOutput}; }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
};

}  // namespace tt::devices
