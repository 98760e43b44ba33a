#pragma once

#include "ui/calibration/calibration_probe.h"

namespace tt::devices {
class Device;
}

namespace tt::ui {

/// A configured probe-mandrel device (devices plugin API) as a calibration probe: its
/// core::DeflectionProbe port for live codes and its TableUploadTarget for the chunked upload and
/// the read-back of version and CRC. The device must outlive the adapter.
class DeviceCalibrationProbe final : public CalibrationProbe {
public:
    /// Throws std::invalid_argument when the device has no deflection-probe port.
    DeviceCalibrationProbe(devices::Device& device, const QString& name, std::optional<int> adcBits = std::nullopt);

    QString name() const override { return m_name; }
    std::optional<int> adcBits() const override { return m_bits; }
    core::DeflectionProbe& port() override;
    bool canUpload() const override;
    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint16_t crc) override;
    ProbeUploadStatus uploadStatus() const override;
    void requestReadback() override;
    std::optional<ProbeTableReadback> readback() const override;

private:
    devices::Device& m_device;
    QString m_name;
    std::optional<int> m_bits;
};

}  // namespace tt::ui
