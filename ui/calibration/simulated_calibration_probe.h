#pragma once

#include <array>
#include <deque>

#include "core/sim/boring/inductive_probe.h"
#include "ui/calibration/calibration_probe.h"

namespace tt::ui {

/// The built-in simulated probe mandrel for the calibration wizard: core::InductiveProbe (the
/// differential bridge with its nonlinear characteristic, ratiometric ADC and noise) on a
/// calibration stand whose screw jack bends the bar, and a microcontroller that takes table
/// uploads in 128-byte chunks (10 ms each), checks the image and reports its version and CRCs
/// (probe protocol 2: images up to 256 KiB, CRC-32C).
/// Time advances only through poll(), so tests are deterministic.
class SimulatedCalibrationProbe final : public CalibrationProbe, private core::DeflectionProbe {
public:
    explicit SimulatedCalibrationProbe(const QString& name,
                                       const core::InductiveProbeConfig& config = core::InductiveProbeConfig{},
                                       unsigned long long seed = 1);

    QString name() const override { return m_name; }
    std::optional<int> adcBits() const override { return m_sensor.config().adcBits; }
    core::DeflectionProbe& port() override { return *this; }
    bool canUpload() const override { return true; }
    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    ProbeUploadStatus uploadStatus() const override { return m_upload; }
    void requestReadback() override {}
    std::optional<ProbeTableReadback> readback() const override { return m_readback; }
    void poll(double seconds) override;
    bool hasJack() const override { return true; }
    void setJackDeflectionMm(int plane, double deflectionMm) override;

    /// Fault switch: the flash stores one byte wrong, so the read-back CRC does not match.
    void setFaultyFlash(bool faulty) { m_faultyFlash = faulty; }
    /// Fault switch: the mandrel stops answering (health error).
    void setDisconnected(bool disconnected) { m_disconnected = disconnected; }
    /// The true tip deflection the jack holds, mm.
    double jackDeflectionMm(int plane) const { return m_jack.at(static_cast<std::size_t>(plane)); }

private:
    core::DeviceHealth health() const override;
    std::optional<core::ProbeSample> takeSample() override;
    void finishUpload();

    QString m_name;
    core::InductiveProbe m_sensor;
    std::array<double, 2> m_jack{};
    double m_timeS = 0.0;
    double m_nextSampleS = 0.0;
    std::deque<core::ProbeSample> m_samples;
    bool m_faultyFlash = false;
    bool m_disconnected = false;
    ProbeUploadStatus m_upload;
    std::vector<std::uint8_t> m_incoming;
    std::uint16_t m_incomingVersion = 0;
    std::size_t m_sentBytes = 0;
    double m_uploadClockS = 0.0;
    std::optional<ProbeTableReadback> m_readback;
};

}  // namespace tt::ui
