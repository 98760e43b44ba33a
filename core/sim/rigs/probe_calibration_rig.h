#pragma once

#include <deque>
#include <random>
#include <vector>

#include "core/calibration/probe_linearisation.h"
#include "core/calibration/table_upload.h"
#include "core/ports/deflection_probe.h"
#include "core/sim/boring/boring_machine.h"
#include "core/sim/boring/inductive_probe.h"

namespace tt::core {

/// The calibration set-up of the probe mandrel on the simulator: a screw jack bends the bar at
/// the tool block to a chosen tip deflection in one plane; a dial indicator (resolution and
/// reading error) gives the reference; the mandrel's ADC is read several times and averaged.
/// Used two ways: whole points at once (measure, sweep), or as the mandrel on its stand, a
/// core::DeflectionProbe whose samples follow the jack as simulated time advances, and a
/// TableUploadPort whose microcontroller takes the table in 128-byte chunks (10 ms each), checks
/// the image, reports its version and CRCs (probe protocol 2) and then linearises its samples.
class ProbeCalibrationRig final : public DeflectionProbe, public TableUploadPort {
public:
    /// Calibrates `plane` of `probe` (outlives the rig) against a reference of the given resolution and noise, µm.
    ProbeCalibrationRig(InductiveProbe& probe, int plane, double referenceResolutionUm, double referenceNoiseUm,
                        unsigned long long seed);

    /// Loads the bar to `tipDeflectionMm`, waits for the filter, reads `readings` codes.
    CalibrationPoint measure(double tipDeflectionMm, int readings);
    /// `config.points` loads evenly over ± spanFraction of the probe's full-scale deflection.
    std::vector<CalibrationPoint> sweep(const ProbeCalibrationConfig& config);
    /// The largest tip deflection the probe reads without saturating the bridge model's u = ±1, mm.
    double fullScaleTipDeflectionMm() const;

    // --- the mandrel on its stand ---
    /// The screw jack bends the bar to `tipDeflectionMm` in the rig's plane from now on.
    void setJackMm(double tipDeflectionMm);
    double jackMm() const { return m_jackMm; }
    /// What the dial indicator shows for the jack's deflection now, µm (its noise, rounded to its resolution).
    double dialIndicatorUm();
    /// Advances simulated time: the analog chain follows the jack, a sample is queued at every
    /// conversion, an upload moves on.
    void advance(double seconds);
    double timeS() const { return m_timeS; }
    /// Fault switch: the flash stores one byte wrong, so the read-back CRC does not match.
    void setFaultyFlash(bool faulty) { m_faultyFlash = faulty; }
    /// Fault switch: the mandrel stops answering (health error, no samples, uploads refused).
    void setDisconnected(bool disconnected) { m_disconnected = disconnected; }

    DeviceHealth health() const override;
    std::optional<ProbeSample> takeSample() override;
    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    UploadLinkStatus uploadStatus() const override { return m_upload; }
    void requestReadback() override {}
    std::optional<TableReadback> readback() const override { return m_readback; }

private:
    double referenceUm(double tipDeflectionMm);
    void queueSample();
    void finishUpload();

    InductiveProbe& m_probe;
    int m_plane;
    double m_resolutionUm;
    double m_noiseUm;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    double m_timeS = 0.0;
    double m_jackMm = 0.0;
    double m_nextSampleS = 0.0;
    std::deque<ProbeSample> m_samples;
    bool m_faultyFlash = false;
    bool m_disconnected = false;
    UploadLinkStatus m_upload;
    std::vector<std::uint8_t> m_incoming;
    std::uint16_t m_incomingVersion = 0;
    std::size_t m_sentBytes = 0;
    double m_uploadClockS = 0.0;
    std::optional<TableReadback> m_readback;
};

}  // namespace tt::core
