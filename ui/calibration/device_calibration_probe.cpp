#include "ui/calibration/device_calibration_probe.h"

#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "devices/api/device.h"

namespace tt::ui {

DeviceCalibrationProbe::DeviceCalibrationProbe(devices::Device& device, const QString& name, std::optional<int> adcBits)
    : m_device(device), m_name(name), m_bits(adcBits) {
    if (!device.deflectionProbe()) throw std::invalid_argument("the device is not a probe mandrel");
}

std::optional<int> DeviceCalibrationProbe::adcBits() const {
    if (m_bits) return m_bits;
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    const std::optional<devices::MandrelInfo> info = target ? target->mandrelInfo() : std::nullopt;
    if (info && info->adcBits && *info->adcBits >= core::kMinAdcBits && *info->adcBits <= core::kMaxAdcBits)
        return info->adcBits;
    return std::nullopt;
}

std::uint8_t DeviceCalibrationProbe::imageFormat() const {
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    const std::optional<devices::MandrelInfo> info = target ? target->mandrelInfo() : std::nullopt;
    return info && info->protocol < 2 ? core::kTableImageFormatCrc16 : core::kTableImageFormat;
}

core::DeflectionProbe& DeviceCalibrationProbe::port() {
    return *m_device.deflectionProbe();
}

bool DeviceCalibrationProbe::canUpload() const {
    return m_device.tableUploadTarget() != nullptr;
}

devices::CalibrationStand* DeviceCalibrationProbe::jack() const {
    devices::CalibrationStand* stand = m_device.calibrationStand();
    return stand && stand->bendsBar() ? stand : nullptr;
}

bool DeviceCalibrationProbe::hasJack() const {
    return jack() != nullptr;
}

void DeviceCalibrationProbe::bendBar(int plane, double tipDeflectionMm) {
    devices::CalibrationStand* stand = jack();
    if (!stand) throw std::invalid_argument("this probe mandrel is not on a stand with a screw jack");
    stand->bendBar(plane, tipDeflectionMm);
    m_engaged = true;
}

void DeviceCalibrationProbe::releaseJack() {
    if (!m_engaged) return;
    if (devices::CalibrationStand* stand = jack()) stand->release();
    m_engaged = false;
}

void DeviceCalibrationProbe::startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) throw std::invalid_argument("this probe cannot take a table upload");
    target->uploadTable(std::move(image), version, crc32c);
}

core::UploadLinkStatus DeviceCalibrationProbe::uploadStatus() const {
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) return {};
    const devices::TableUploadStatus s = target->uploadStatus();
    core::UploadLinkStatus out;
    switch (s.phase) {
        case devices::TableUploadStatus::Phase::Idle:
            out.phase = core::UploadLinkStatus::Phase::Idle;
            break;
        case devices::TableUploadStatus::Phase::Running:
            out.phase = core::UploadLinkStatus::Phase::Running;
            break;
        case devices::TableUploadStatus::Phase::Done:
            out.phase = core::UploadLinkStatus::Phase::Done;
            break;
        case devices::TableUploadStatus::Phase::Failed:
            out.phase = core::UploadLinkStatus::Phase::Failed;
            break;
    }
    out.progress = s.progress;
    out.message = s.message.toStdString();
    return out;
}

void DeviceCalibrationProbe::requestReadback() {
    m_device.testConnection();  // a probe answers with its table's version and CRC
}

std::optional<core::TableReadback> DeviceCalibrationProbe::readback() const {
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) return std::nullopt;
    const std::optional<devices::MandrelTableInfo> info = target->tableInfo();
    if (!info) return std::nullopt;
    return core::TableReadback{info->version, info->crc, info->crc32c, info->sizeBytes, info->valid};
}

}  // namespace tt::ui
