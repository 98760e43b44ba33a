#pragma once

#include <QList>
#include <QString>
#include <optional>

namespace tt::devices {

/// What a device instance provides to the engine: one of the ports in core/ports.
enum class DeviceKind {
    Gauge,             ///< core::DiameterGauge: finished diameters (paper 000)
    Probe,             ///< core::DeflectionProbe: boring-bar deflection (paper 001, way 2)
    DriveCurrent,      ///< core::DriveCurrentReadout: cross-feed current, velocity, position (paper 001, way 1)
    CorrectionOutput,  ///< core::CorrectionOutput: corrected path or dynamic X offset to the CNC
};

/// All kinds, in the order the Devices page lists them.
inline const QList<DeviceKind>& allDeviceKinds() {
    static const QList<DeviceKind> kinds{DeviceKind::Gauge, DeviceKind::Probe, DeviceKind::DriveCurrent,
                                         DeviceKind::CorrectionOutput};
    return kinds;
}

/// Stable, untranslated key stored in settings ("gauge", "probe", "drive-current", "correction-output").
QString kindKey(DeviceKind kind);
/// The kind of a key; nullopt for an unknown key.
std::optional<DeviceKind> kindFromKey(const QString& key);
/// Name for messages and the Devices page in the user's language ("Gauge micrometer"; translated
/// in the context "DeviceKinds" when a translator is installed).
QString kindName(DeviceKind kind);

}  // namespace tt::devices
