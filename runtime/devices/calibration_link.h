#pragma once

#include <QString>

#include "core/loop/boring_relays.h"

namespace tt::runtime {

/// A probe mandrel or a drive read-out of the device thread as a calibration wizard in the GUI thread reads
/// it: the device thread passes the instrument's samples and health into thread-safe relays (DeviceHost's
/// calibration pump), the wizard takes them here. Commands to the instrument (bend the bar, load the tool
/// holder, upload a table) go through DeviceHub. Thread-safe.
class CalibrationLink {
public:
    explicit CalibrationLink(QString deviceId) : m_deviceId(std::move(deviceId)) {}

    /// The instrument's id on the Devices page.
    const QString& deviceId() const { return m_deviceId; }
    /// Raw ADC codes of a probe mandrel, with its health.
    core::ProbeRelay& probe() { return m_probe; }
    /// Current, velocity and position of a drive read-out, with its health.
    core::DriveRelay& drive() { return m_drive; }

private:
    QString m_deviceId;
    core::ProbeRelay m_probe;
    core::DriveRelay m_drive;
};

}  // namespace tt::runtime
