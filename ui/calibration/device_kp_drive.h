#pragma once

#include <QString>
#include <memory>

#include "core/ports/drive_current.h"

namespace tt::runtime {
class CalibrationLink;
class DeviceHub;
}  // namespace tt::runtime

namespace tt::ui {

/// A configured drive-current device (devices plugin API: the Modbus read-out of the drive or the
/// PLC, or the simulator's drive) as the cross-feed drive of the k_p wizard: its current,
/// velocity and position read-out while the cross feed dithers, and the hydraulic jack of its
/// calibration stand when the device offers one (on a machine the operator applies the loads).
/// The device lives in the device thread (runtime::DeviceHub); its samples reach the wizard through a
/// runtime::CalibrationLink. The hub must outlive the adapter; the owner releases a jack the adapter engaged
/// (releaseJack) while the device is still there.
class DeviceKpDrive final {
public:
    /// Throws std::invalid_argument when `deviceId` is no drive-current read-out of the hub.
    DeviceKpDrive(runtime::DeviceHub& hub, const QString& deviceId, const QString& name);
    DeviceKpDrive(const DeviceKpDrive&) = delete;
    DeviceKpDrive& operator=(const DeviceKpDrive&) = delete;

    QString name() const { return m_name; }
    core::DriveCurrentReadout& readout();
    /// The device's calibration stand has a hydraulic jack that applies a known load.
    bool hasJack() const;
    /// The jack pushes the tool holder towards the axis with `loadN` (throws std::invalid_argument without one).
    void applyLoadN(double loadN);
    /// Takes away the jack this adapter engaged.
    void releaseJack();
    /// The device behind the adapter (its id on the Devices page).
    const QString& deviceId() const { return m_deviceId; }

private:
    runtime::DeviceHub& m_hub;
    QString m_deviceId;
    std::shared_ptr<runtime::CalibrationLink> m_link;
    QString m_name;
    bool m_engaged = false;
};

}  // namespace tt::ui
