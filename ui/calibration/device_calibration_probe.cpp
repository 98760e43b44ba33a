#include "ui/calibration/device_calibration_probe.h"

#include <stdexcept>

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

void DeviceCalibrationProbe::startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) throw std::invalid_argument("this probe cannot take a table upload");
    target->uploadTable(std::move(image), version, crc32c);
}

ProbeUploadStatus DeviceCalibrationProbe::uploadStatus() const {
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) return {};
    const devices::TableUploadStatus s = target->uploadStatus();
    ProbeUploadStatus out;
    switch (s.phase) {
        case devices::TableUploadStatus::Phase::Idle:
            out.phase = ProbeUploadStatus::Phase::Idle;
            break;
        case devices::TableUploadStatus::Phase::Running:
            out.phase = ProbeUploadStatus::Phase::Running;
            break;
        case devices::TableUploadStatus::Phase::Done:
            out.phase = ProbeUploadStatus::Phase::Done;
            break;
        case devices::TableUploadStatus::Phase::Failed:
            out.phase = ProbeUploadStatus::Phase::Failed;
            break;
    }
    out.progress = s.progress;
    out.message = s.message;
    return out;
}

void DeviceCalibrationProbe::requestReadback() {
    m_device.testConnection();  // a probe answers with its table's version and CRC
}

std::optional<ProbeTableReadback> DeviceCalibrationProbe::readback() const {
    const devices::TableUploadTarget* target = m_device.tableUploadTarget();
    if (!target) return std::nullopt;
    const std::optional<devices::MandrelTableInfo> info = target->tableInfo();
    if (!info) return std::nullopt;
    return ProbeTableReadback{info->version, info->crc, info->crc32c, info->sizeBytes, info->valid};
}

}  // namespace tt::ui
