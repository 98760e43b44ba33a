#pragma once

#include <QString>

#include "ui/calibration/kp_drive_source.h"

namespace tt::devices {
class Device;
}

namespace tt::ui {

/// A configured drive-current device (devices plugin API: the Modbus read-out of the drive or the
/// PLC, or the simulator's drive) as the cross-feed drive of the k_p wizard: its current,
/// velocity and position read-out while the cross feed dithers. The samples arrive in the event
/// loop, so poll() has nothing to do, and the operator applies the known loads (no jack). The
/// device must outlive the adapter.
class DeviceKpDrive final : public KpDriveSource {
public:
    /// Throws std::invalid_argument when the device has no drive-current read-out.
    DeviceKpDrive(devices::Device& device, const QString& name);

    QString name() const override { return m_name; }
    core::DriveCurrentReadout& readout() override;
    /// The device behind the adapter.
    const devices::Device& device() const { return m_device; }

private:
    devices::Device& m_device;
    QString m_name;
};

}  // namespace tt::ui
