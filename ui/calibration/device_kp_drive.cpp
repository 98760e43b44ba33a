#include "ui/calibration/device_kp_drive.h"

#include <stdexcept>

#include "devices/api/device.h"

namespace tt::ui {

DeviceKpDrive::DeviceKpDrive(devices::Device& device, const QString& name) : m_device(device), m_name(name) {
    if (!device.driveCurrentReadout()) throw std::invalid_argument("the device is not a drive-current read-out");
}

core::DriveCurrentReadout& DeviceKpDrive::readout() {
    return *m_device.driveCurrentReadout();
}

}  // namespace tt::ui
