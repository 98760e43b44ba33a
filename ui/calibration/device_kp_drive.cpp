#include "ui/calibration/device_kp_drive.h"

#include <stdexcept>

#include "runtime/devices/calibration_link.h"
#include "runtime/devices/device_hub.h"

namespace tt::ui {

DeviceKpDrive::DeviceKpDrive(runtime::DeviceHub& hub, const QString& deviceId, const QString& name)
    : m_hub(hub), m_deviceId(deviceId), m_name(name) {
    const runtime::DeviceView* v = hub.view(deviceId);
    if (!v || v->kind != devices::DeviceKind::DriveCurrent)
        throw std::invalid_argument("the device is not a drive-current read-out");
    m_link = hub.calibrationLink(deviceId);
}

core::DriveCurrentReadout& DeviceKpDrive::readout() {
    return m_link->drive();
}

bool DeviceKpDrive::hasJack() const {
    const runtime::DeviceView* v = m_hub.view(m_deviceId);
    return v && v->standAppliesLoad;
}

void DeviceKpDrive::applyLoadN(double loadN) {
    if (!hasJack()) throw std::invalid_argument("this cross feed is not on a stand with a hydraulic jack");
    m_hub.applyLoadN(m_deviceId, loadN);
    m_engaged = true;
}

void DeviceKpDrive::releaseJack() {
    if (!m_engaged) return;
    m_hub.releaseJack(m_deviceId);
    m_engaged = false;
}

}  // namespace tt::ui
