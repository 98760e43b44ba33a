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

devices::CalibrationStand* DeviceKpDrive::jack() const {
    devices::CalibrationStand* stand = m_device.calibrationStand();
    return stand && stand->appliesLoad() ? stand : nullptr;
}

bool DeviceKpDrive::hasJack() const {
    return jack() != nullptr;
}

void DeviceKpDrive::applyLoadN(double loadN) {
    devices::CalibrationStand* stand = jack();
    if (!stand) throw std::invalid_argument("this cross feed is not on a stand with a hydraulic jack");
    stand->applyLoadN(loadN);
    m_engaged = true;
}

void DeviceKpDrive::releaseJack() {
    if (!m_engaged) return;
    if (devices::CalibrationStand* stand = jack()) stand->release();
    m_engaged = false;
}

}  // namespace tt::ui
