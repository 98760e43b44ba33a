#include "ui/calibration/device_calibration_probe.h"

#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "runtime/devices/calibration_link.h"
#include "runtime/devices/device_hub.h"

namespace tt::ui {

DeviceCalibrationProbe::DeviceCalibrationProbe(runtime::DeviceHub& hub, const QString& deviceId, const QString& name,
                                               std::optional<int> adcBits)
    : m_hub(hub), m_deviceId(deviceId), m_name(name), m_bits(adcBits) {
    const runtime::DeviceView* v = view();
    if (!v || v->kind != devices::DeviceKind::Probe) throw std::invalid_argument("the device is not a probe mandrel");
    m_link = hub.calibrationLink(deviceId);
}

const runtime::DeviceView* DeviceCalibrationProbe::view() const {
    return m_hub.view(m_deviceId);
}

std::optional<int> DeviceCalibrationProbe::adcBits() const {
    if (m_bits) return m_bits;
    const runtime::DeviceView* v = view();
    const std::optional<devices::MandrelInfo> info = v ? v->mandrel : std::nullopt;
    if (info && info->adcBits && *info->adcBits >= core::kMinAdcBits && *info->adcBits <= core::kMaxAdcBits)
        return info->adcBits;
    return std::nullopt;
}

std::uint8_t DeviceCalibrationProbe::imageFormat() const {
    const runtime::DeviceView* v = view();
    const std::optional<devices::MandrelInfo> info = v ? v->mandrel : std::nullopt;
    return info && info->protocol < 2 ? core::kTableImageFormatCrc16 : core::kTableImageFormat;
}

core::DeflectionProbe& DeviceCalibrationProbe::port() {
    return m_link->probe();
}

bool DeviceCalibrationProbe::canUpload() const {
    const runtime::DeviceView* v = view();
    return v && v->uploadsTable;
}

bool DeviceCalibrationProbe::hasJack() const {
    const runtime::DeviceView* v = view();
    return v && v->standBendsBar;
}

void DeviceCalibrationProbe::bendBar(int plane, double tipDeflectionMm) {
    if (!hasJack()) throw std::invalid_argument("this probe mandrel is not on a stand with a screw jack");
    m_hub.bendBar(m_deviceId, plane, tipDeflectionMm);
    m_engaged = true;
}

void DeviceCalibrationProbe::releaseJack() {
    if (!m_engaged) return;
    m_hub.releaseJack(m_deviceId);
    m_engaged = false;
}

void DeviceCalibrationProbe::startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    if (!canUpload()) throw std::invalid_argument("this probe cannot take a table upload");
    m_hub.uploadTable(m_deviceId, image, version, crc32c);
    m_hub.sync();  // the upload's first status is in the snapshot before the wizard polls it
}

core::UploadLinkStatus DeviceCalibrationProbe::uploadStatus() const {
    const runtime::DeviceView* v = view();
    if (!v || !v->uploadsTable) return {};
    const devices::TableUploadStatus& s = v->upload;
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
    m_hub.testConnection(m_deviceId);  // a probe answers with its table's version and CRC
}

std::optional<core::TableReadback> DeviceCalibrationProbe::readback() const {
    const runtime::DeviceView* v = view();
    if (!v || !v->table) return std::nullopt;
    const devices::MandrelTableInfo& info = *v->table;
    return core::TableReadback{info.version, info.crc, info.crc32c, info.sizeBytes, info.valid};
}

}  // namespace tt::ui
