#include "core/sim/rigs/probe_calibration_rig.h"

#include <cmath>
#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {

namespace {
constexpr std::size_t kChunkBytes = 128;
constexpr double kChunkS = 0.01;
constexpr std::size_t kMaxImageBytes = 256 * 1024;  ///< what the mandrel's flash holds (probe protocol 2)
constexpr std::size_t kMaxQueued = 5000;
}  // namespace

ProbeCalibrationRig::ProbeCalibrationRig(InductiveProbe& probe, int plane, double referenceResolutionUm,
                                         double referenceNoiseUm, unsigned long long seed)
    : m_probe(probe), m_plane(plane), m_resolutionUm(referenceResolutionUm), m_noiseUm(referenceNoiseUm), m_rng(seed) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("probe plane must be 0 (X) or 1 (Y)");
    if (!(referenceResolutionUm >= 0.0) || !(referenceNoiseUm >= 0.0))
        throw std::invalid_argument("reference resolution and noise must not be negative");
}

double ProbeCalibrationRig::fullScaleTipDeflectionMm() const {
    return m_probe.config().fullScaleGapMm / sensorToTipRatio(m_probe.config().sensorPositionFraction);
}

double ProbeCalibrationRig::referenceUm(double tipDeflectionMm) {
    double reference = tipDeflectionMm * 1000.0 + m_noiseUm * m_normal(m_rng);
    if (m_resolutionUm > 0.0) reference = std::round(reference / m_resolutionUm) * m_resolutionUm;
    return reference;
}

CalibrationPoint ProbeCalibrationRig::measure(double tipDeflectionMm, int readings) {
    if (readings < 1) throw std::invalid_argument("at least one reading per point is needed");
    const double x = m_plane == 0 ? tipDeflectionMm : 0.0;
    const double y = m_plane == 1 ? tipDeflectionMm : 0.0;
    m_probe.settle(x, y);
    const double period = 1.0 / m_probe.config().sampleRateHz;
    double sum = 0.0;
    for (int i = 0; i < readings; ++i) {
        m_probe.advance(period, x, y);
        m_timeS += period;
        sum += m_probe.convert(m_timeS)[static_cast<std::size_t>(m_plane)];
    }
    CalibrationPoint p;
    p.adcCode = sum / readings;
    p.referenceUm = referenceUm(tipDeflectionMm);
    return p;
}

std::vector<CalibrationPoint> ProbeCalibrationRig::sweep(const ProbeCalibrationConfig& config) {
    if (config.points < 2) throw std::invalid_argument("a calibration sweep needs at least two points");
    const double span = config.spanFraction * fullScaleTipDeflectionMm();
    std::vector<CalibrationPoint> points;
    for (int i = 0; i < config.points; ++i) {
        const double deflection = -span + 2.0 * span * i / (config.points - 1);
        points.push_back(measure(deflection, config.readingsPerPoint));
    }
    return points;
}

void ProbeCalibrationRig::setJackMm(double tipDeflectionMm) {
    if (!std::isfinite(tipDeflectionMm) || std::abs(tipDeflectionMm) > 5.0)
        throw std::invalid_argument("the jack bends the bar by at most ±5 mm");
    m_jackMm = tipDeflectionMm;
}

double ProbeCalibrationRig::dialIndicatorUm() {
    return referenceUm(m_jackMm);
}

DeviceHealth ProbeCalibrationRig::health() const {
    if (m_disconnected) return {DeviceState::Error, "the simulated mandrel does not answer"};
    return {DeviceState::Ready, {}};
}

std::optional<ProbeSample> ProbeCalibrationRig::takeSample() {
    if (m_samples.empty() || m_disconnected) return std::nullopt;
    const ProbeSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

void ProbeCalibrationRig::queueSample() {
    ProbeSample s;
    s.timeS = m_timeS;
    s.adcCode = m_probe.convert(m_timeS);
    for (std::size_t p = 0; p < 2; ++p) {
        const auto& table = m_probe.table(static_cast<int>(p));
        if (table) s.linearised = true;
        s.deflectionMm[p] = table ? table->deflectionUm(s.adcCode[p]) / 1000.0 : 0.0;
    }
    if (m_disconnected) return;
    m_samples.push_back(s);
    if (m_samples.size() > kMaxQueued) m_samples.pop_front();
}

void ProbeCalibrationRig::advance(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) throw std::invalid_argument("time moves forward only");
    const double x = m_plane == 0 ? m_jackMm : 0.0;
    const double y = m_plane == 1 ? m_jackMm : 0.0;
    const double period = 1.0 / m_probe.config().sampleRateHz;
    const double end = m_timeS + seconds;
    if (m_nextSampleS < m_timeS) m_nextSampleS = m_timeS;
    while (m_nextSampleS <= end) {
        m_probe.advance(m_nextSampleS - m_timeS, x, y);
        m_timeS = m_nextSampleS;
        queueSample();
        m_nextSampleS += period;
    }
    m_probe.advance(end - m_timeS, x, y);
    m_timeS = end;
    if (m_upload.phase != UploadLinkStatus::Phase::Running) return;
    m_uploadClockS += seconds;
    while (m_uploadClockS >= kChunkS && m_sentBytes < m_incoming.size()) {
        m_uploadClockS -= kChunkS;
        m_sentBytes = std::min(m_incoming.size(), m_sentBytes + kChunkBytes);
    }
    m_upload.progress = static_cast<double>(m_sentBytes) / static_cast<double>(m_incoming.size());
    if (m_sentBytes == m_incoming.size()) finishUpload();
}

void ProbeCalibrationRig::startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    if (m_disconnected) throw std::invalid_argument("the mandrel does not answer");
    if (m_upload.phase == UploadLinkStatus::Phase::Running) throw std::invalid_argument("an upload is already running");
    if (image.empty() || image.size() > kMaxImageBytes)
        throw std::invalid_argument("the image has " + std::to_string(image.size()) +
                                    " bytes; the mandrel stores 1 .. 262144");
    if (core::crc32c(image) != crc32c) throw std::invalid_argument("the image does not have the announced CRC");
    m_incoming = std::move(image);
    m_incomingVersion = version;
    m_sentBytes = 0;
    m_uploadClockS = 0.0;
    m_upload = {UploadLinkStatus::Phase::Running, 0.0, {}};
}

void ProbeCalibrationRig::finishUpload() {
    std::vector<std::uint8_t> stored = m_incoming;
    if (m_faultyFlash && stored.size() > 40) stored[40] ^= 0x10;
    m_readback = TableReadback{m_incomingVersion, crc16Ccitt(stored), core::crc32c(stored),
                               static_cast<std::uint32_t>(stored.size()), false};
    m_upload = {UploadLinkStatus::Phase::Done, 1.0, {}};
    try {
        const TableImage image = decodeTableImage(stored);
        m_probe.setTable(image.info.plane, image.table);
        m_readback->valid = true;
    } catch (const std::invalid_argument&) {
        // Stored but rejected by the firmware: the read-back says the table is not valid.
    }
}

}  // namespace tt::core
