#pragma once

#include "ui/calibration/calibration_probe.h"

namespace tt::devices {
class Device;
}

namespace tt::ui {

/// A configured probe-mandrel device (devices plugin API) as a calibration probe: its
/// core::DeflectionProbe port for live codes and its TableUploadTarget for the chunked upload and
/// the read-back of version and CRC; the ADC resolution and image format follow what the
/// mandrel reports. The device must outlive the adapter.
class DeviceCalibrationProbe final : public CalibrationProbe {
public:
    /// Throws std::invalid_argument when the device has no deflection-probe port. Without
    /// `adcBits` the resolution is the one the mandrel reports (probe protocol 2's DEVICE_INFO).
    DeviceCalibrationProbe(devices::Device& device, const QString& name, std::optional<int> adcBits = std::nullopt);

    QString name() const override { return m_name; }
    std::optional<int> adcBits() const override;
    core::DeflectionProbe& port() override;
    bool canUpload() const override;
    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    std::uint8_t imageFormat() const override;
    ProbeUploadStatus uploadStatus() const override;
    void requestReadback() override;
    /// The device behind the adapter.
    const devices::Device& device() const { return m_device; }
    std::optional<ProbeTableReadback> readback() const override;

private:
    devices::Device& m_device;
    QString m_name;
    std::optional<int> m_bits;
};

}  // namespace tt::ui
