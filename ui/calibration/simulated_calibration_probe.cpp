#include "ui/calibration/simulated_calibration_probe.h"

#include <QCoreApplication>
#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::ui {

namespace {
constexpr std::size_t kChunkBytes = 128;
constexpr double kChunkS = 0.01;
constexpr std::size_t kMaxImageBytes = 256 * 1024;  ///< what the mandrel's flash holds (probe protocol 2)
}  // namespace

SimulatedCalibrationProbe::SimulatedCalibrationProbe(const QString& name, const core::InductiveProbeConfig& config,
                                                     unsigned long long seed)
    : m_name(name), m_sensor(config, seed) {
    m_sensor.settle(0.0, 0.0);
}

core::DeviceHealth SimulatedCalibrationProbe::health() const {
    if (m_disconnected) return {core::DeviceState::Error, "the simulated mandrel does not answer (cable unplugged)"};
    return {core::DeviceState::Ready, {}};
}

std::optional<core::ProbeSample> SimulatedCalibrationProbe::takeSample() {
    if (m_samples.empty() || m_disconnected) return std::nullopt;
    core::ProbeSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

void SimulatedCalibrationProbe::setJackDeflectionMm(int plane, double deflectionMm) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("plane must be 0 (X) or 1 (Y)");
    m_jack[static_cast<std::size_t>(plane)] = deflectionMm;
}

void SimulatedCalibrationProbe::poll(double seconds) {
    const double period = 1.0 / m_sensor.config().sampleRateHz;
    const double end = m_timeS + seconds;
    while (m_nextSampleS <= end) {
        m_sensor.advance(m_nextSampleS - m_timeS, m_jack[0], m_jack[1]);
        m_timeS = m_nextSampleS;
        core::ProbeSample s;
        s.timeS = m_timeS;
        s.adcCode = m_sensor.convert(m_timeS);
        s.linearised = m_sensor.table(0).has_value() || m_sensor.table(1).has_value();
        for (int p = 0; p < 2; ++p) {
            const auto& table = m_sensor.table(p);
            s.deflectionMm[static_cast<std::size_t>(p)] =
                table ? table->deflectionUm(s.adcCode[static_cast<std::size_t>(p)]) / 1000.0 : 0.0;
        }
        if (!m_disconnected) m_samples.push_back(s);
        if (m_samples.size() > 5000) m_samples.pop_front();
        m_nextSampleS += period;
    }
    m_sensor.advance(end - m_timeS, m_jack[0], m_jack[1]);
    m_timeS = end;
    if (m_upload.phase != ProbeUploadStatus::Phase::Running) return;
    m_uploadClockS += seconds;
    while (m_uploadClockS >= kChunkS && m_sentBytes < m_incoming.size()) {
        m_uploadClockS -= kChunkS;
        m_sentBytes = std::min(m_incoming.size(), m_sentBytes + kChunkBytes);
    }
    m_upload.progress = static_cast<double>(m_sentBytes) / static_cast<double>(m_incoming.size());
    m_upload.message = QCoreApplication::translate("SimulatedCalibrationProbe", "Sending chunk %1 of %2")
                           .arg((m_sentBytes + kChunkBytes - 1) / kChunkBytes)
                           .arg((m_incoming.size() + kChunkBytes - 1) / kChunkBytes);
    if (m_sentBytes == m_incoming.size()) finishUpload();
}

void SimulatedCalibrationProbe::startUpload(std::vector<std::uint8_t> image, std::uint16_t version,
                                            std::uint32_t crc32c) {
    if (m_disconnected) throw std::invalid_argument("the mandrel does not answer");
    if (m_upload.phase == ProbeUploadStatus::Phase::Running)
        throw std::invalid_argument("an upload is already running");
    if (image.empty() || image.size() > kMaxImageBytes)
        throw std::invalid_argument("the image has " + std::to_string(image.size()) +
                                    " bytes; the mandrel stores 1 .. 262144");
    if (core::crc32c(image) != crc32c) throw std::invalid_argument("the image does not have the announced CRC");
    m_incoming = std::move(image);
    m_incomingVersion = version;
    m_sentBytes = 0;
    m_uploadClockS = 0.0;
    m_upload = {ProbeUploadStatus::Phase::Running, 0.0, {}};
}

void SimulatedCalibrationProbe::finishUpload() {
    std::vector<std::uint8_t> stored = m_incoming;
    if (m_faultyFlash && stored.size() > 40) stored[40] ^= 0x10;
    m_readback = ProbeTableReadback{m_incomingVersion, core::crc16Ccitt(stored), core::crc32c(stored),
                                    static_cast<std::uint32_t>(stored.size()), false};
    try {
        const core::TableImage image = core::decodeTableImage(stored);
        m_sensor.setTable(image.info.plane, image.table);
        m_readback->valid = true;
        m_upload = {ProbeUploadStatus::Phase::Done, 1.0,
                    QCoreApplication::translate("SimulatedCalibrationProbe", "Stored in the mandrel")};
    } catch (const std::invalid_argument& e) {
        m_upload = {ProbeUploadStatus::Phase::Done, 1.0,
                    QCoreApplication::translate("SimulatedCalibrationProbe", "Stored, but the mandrel rejects it: %1")
                        .arg(QString::fromStdString(e.what()))};
    }
}

}  // namespace tt::ui
