#pragma once

#include <QCoreApplication>

#include "devices/api/device_plugin.h"

namespace tt::devices {

/// Factory of serial probe mandrels (see SerialProbeDevice); any number at once (e.g. two
/// boring bars). Exported by the Qt plugin in probe_mandrel_plugin.h.
class ProbeMandrelFactory : public DevicePlugin {
public:
    QString pluginId() const override { return QStringLiteral("probe-mandrel"); }
    QString displayName() const override { return QCoreApplication::translate("ProbeMandrel", "Serial RS-232/RS-485"); }
    QList<DeviceKind> kinds() const override { return {DeviceKind::Probe}; }
    SettingsSchema settingsSchema(DeviceKind kind) const override;
    std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings, const DeviceContext& context) override;
};

}  // namespace tt::devices
