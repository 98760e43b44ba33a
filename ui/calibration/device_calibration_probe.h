#pragma once

#include <QString>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/calibration/table_upload.h"
#include "core/ports/deflection_probe.h"

namespace tt::runtime {
class CalibrationLink;
class DeviceHub;
struct DeviceView;
}  // namespace tt::runtime

namespace tt::ui {

/// A configured probe-mandrel device (it lives in the device thread, runtime::DeviceHub) as the probe wizard
/// uses it from the GUI thread: its live codes through a runtime::CalibrationLink (a relay the device thread
/// fills), the table upload as the engine's upload port (chunked upload, read-back of version and CRC), the
/// ADC resolution and image format the mandrel reports (from its snapshot), and the screw jack of its
/// calibration stand when it sits on one. The hub must outlive the adapter; the owner releases a jack the
/// adapter engaged (releaseJack) while the device is still there.
class DeviceCalibrationProbe final : public core::TableUploadPort {
public:
    /// Throws std::invalid_argument when `deviceId` is no probe mandrel of the hub. Without `adcBits` the
    /// resolution is the one the mandrel reports (probe protocol 2's DEVICE_INFO).
    DeviceCalibrationProbe(runtime::DeviceHub& hub, const QString& deviceId, const QString& name,
                           std::optional<int> adcBits = std::nullopt);
    DeviceCalibrationProbe(const DeviceCalibrationProbe&) = delete;
    DeviceCalibrationProbe& operator=(const DeviceCalibrationProbe&) = delete;

    QString name() const { return m_name; }
    /// ADC resolution, bits, when the probe knows it (otherwise the wizard asks).
    std::optional<int> adcBits() const;
    /// The live samples (raw ADC code per plane).
    core::DeflectionProbe& port();
    bool canUpload() const;
    /// The table image format the mandrel's firmware reads: 2, or 1 for probe protocol 1.
    std::uint8_t imageFormat() const;

    /// The device's calibration stand has a screw jack that bends the bar.
    bool hasJack() const;
    /// Bends the bar to a tip deflection in `plane`, mm (throws std::invalid_argument without a jack).
    void bendBar(int plane, double tipDeflectionMm);
    /// Takes away the jack this adapter engaged.
    void releaseJack();

    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    core::UploadLinkStatus uploadStatus() const override;
    void requestReadback() override;
    std::optional<core::TableReadback> readback() const override;

    /// The device behind the adapter (its id on the Devices page).
    const QString& deviceId() const { return m_deviceId; }

private:
    const runtime::DeviceView* view() const;

    runtime::DeviceHub& m_hub;
    QString m_deviceId;
    std::shared_ptr<runtime::CalibrationLink> m_link;
    QString m_name;
    std::optional<int> m_bits;
    bool m_engaged = false;
};

}  // namespace tt::ui
