#include "devices/api/device_kind.h"

#include <QCoreApplication>

namespace tt::devices {

QString kindKey(DeviceKind kind) {
    switch (kind) {
        case DeviceKind::Gauge:
            return QStringLiteral("gauge");
        case DeviceKind::Probe:
            return QStringLiteral("probe");
        case DeviceKind::DriveCurrent:
            return QStringLiteral("drive-current");
        case DeviceKind::CorrectionOutput:
            return QStringLiteral("correction-output");
    }
    return {};
}

std::optional<DeviceKind> kindFromKey(const QString& key) {
    for (DeviceKind kind : allDeviceKinds())
        if (kindKey(kind) == key) return kind;
    return std::nullopt;
}

QString kindName(DeviceKind kind) {
    switch (kind) {
        case DeviceKind::Gauge:
            return QCoreApplication::translate("DeviceKinds", "Gauge micrometer");
        case DeviceKind::Probe:
            return QCoreApplication::translate("DeviceKinds", "Probe mandrel");
        case DeviceKind::DriveCurrent:
            return QCoreApplication::translate("DeviceKinds", "Drive-current readout");
        case DeviceKind::CorrectionOutput:
            return QCoreApplication::translate("DeviceKinds", "Correction output to the CNC");
    }
    return {};
}

}  // namespace tt::devices
