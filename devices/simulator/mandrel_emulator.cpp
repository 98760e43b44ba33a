#include "devices/simulator/mandrel_emulator.h"

#include <algorithm>
#include <cmath>

#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"
#include "core/sim/boring/inductive_probe.h"

namespace tt::devices {

using namespace probe;

namespace {

/// The bridge and ADC of the emulated mandrel (static characteristic only: no noise, no filter).
const core::InductiveProbe& bridge() {
    static const core::InductiveProbe probe = [] {
        core::InductiveProbeConfig c;
        c.adcBits = MandrelEmulator::kAdcBits;
        c.fullScaleGapMm = MandrelEmulator::kFullScaleGapMm;
        c.bridgeCoefficients = {0.0, MandrelEmulator::kLinearTerm, 0.0, MandrelEmulator::kCubicTerm};
        c.sensorPositionFraction = MandrelEmulator::kSensorPositionFraction;
        return core::InductiveProbe(c, 1);
    }();
    return probe;
}

}  // namespace

MandrelEmulator::MandrelEmulator(int protocol) : m_protocol(protocol) {
    if (protocol != 1 && protocol != kProtocolVersion)
        throw std::invalid_argument("the emulated mandrel speaks probe protocol 1 or 2");
    m_source = [](double) { return std::array<double, 2>{0.020, -0.005}; };
}

double MandrelEmulator::exactCode(double deflectionMm) {
    return bridge().staticCode(deflectionMm);
}

double MandrelEmulator::fullScaleDeflectionMm() {
    return kFullScaleGapMm / core::sensorToTipRatio(kSensorPositionFraction);
}

void MandrelEmulator::setDeflectionSource(std::function<std::array<double, 2>(double)> source) {
    if (source) m_source = std::move(source);
}

const std::vector<std::uint8_t>& MandrelEmulator::deliveryTableImage() {
    static const std::vector<std::uint8_t> image = [] {
        std::vector<core::CalibrationPoint> points;
        const double spanMm = 0.9 * fullScaleDeflectionMm();
        for (int i = 0; i <= 40; ++i) {
            const double mm = -spanMm + 2.0 * spanMm * i / 40.0;
            points.push_back({mm * 1000.0, exactCode(mm), 0});
        }
        const core::Linearisation lin = core::linearise(points, kAdcBits, 3);
        core::TableImageInfo info;
        info.version = 1;
        info.degree = 3;
        return core::encodeTableImage(lin.table, info);
    }();
    return image;
}

std::int32_t MandrelEmulator::adcCode(double deflectionMm) {
    return static_cast<std::int32_t>(
        std::clamp(std::round(exactCode(deflectionMm)), 0.0, static_cast<double>(kMaxCode)));
}

void MandrelEmulator::store(std::vector<std::uint8_t> image, std::uint16_t version) {
    m_table = std::move(image);
    m_tableVersion = version;
    m_tableCrc = core::crc16Ccitt(m_table);  // what the flash really holds
    m_tableCrc32 = core::crc32c(m_table);
    m_tableValid = !m_table.empty();
}

void MandrelEmulator::preloadTable(std::vector<std::uint8_t> image, std::uint16_t version) {
    store(std::move(image), version);
}

TableInfoPayload MandrelEmulator::tableInfo() const {
    TableInfoPayload info{m_tableVersion, m_tableCrc, static_cast<std::uint32_t>(m_table.size()), m_tableValid, {}};
    if (m_protocol >= 2) info.crc32c = m_tableCrc32;
    return info;
}

std::vector<std::uint8_t> MandrelEmulator::send(MessageType type, const std::vector<std::uint8_t>& payload) {
    if (m_silent) return {};
    const std::uint8_t sequence = m_sequence++;
    if (m_drop > 0) {
        --m_drop;
        return {};
    }
    std::vector<std::uint8_t> frame = encodeFrame(sequence, type, payload);
    if (m_corrupt > 0) {
        --m_corrupt;
        frame[kHeaderBytes + payload.size() / 2] ^= 0x10;  // a bit error on the line (in the CRC if no payload)
    }
    ++m_framesSent;
    if (m_duplicate > 0) {
        --m_duplicate;
        std::vector<std::uint8_t> twice = frame;
        twice.insert(twice.end(), frame.begin(), frame.end());
        return twice;
    }
    return frame;
}

std::vector<std::uint8_t> MandrelEmulator::ack(std::uint8_t command, AckResult result, std::uint32_t detail) {
    return send(MessageType::Ack, encodeAck({command, result, detail}));
}

std::vector<std::uint8_t> MandrelEmulator::receive(std::span<const std::uint8_t> bytes) {
    std::vector<std::uint8_t> out;
    for (const Frame& frame : m_reader.feed(bytes)) {
        const auto reply = handle(frame);
        out.insert(out.end(), reply.begin(), reply.end());
    }
    return out;
}

std::vector<std::uint8_t> MandrelEmulator::handle(const Frame& frame) {
    ++m_commands;
    const std::uint8_t cmd = frame.type;
    const bool v2 = m_protocol >= 2;
    switch (static_cast<MessageType>(cmd)) {
        case MessageType::StartStream:
            m_streaming = true;
            m_nextSampleS = m_timeS;
            return ack(cmd, AckResult::Ok);
        case MessageType::StopStream:
            m_streaming = false;
            return ack(cmd, AckResult::Ok);
        case MessageType::SetRate: {
            const auto rate = decodeRate(frame.payload);
            if (!rate) return ack(cmd, AckResult::BadArgument, static_cast<std::uint32_t>(m_rateHz));
            m_rateHz = rate.value();
            return ack(cmd, AckResult::Ok, static_cast<std::uint32_t>(m_rateHz));
        }
        case MessageType::ReadTableInfo:
            return send(MessageType::TableInfo, encodeTableInfo(tableInfo()));
        case MessageType::ReadTableInfo32:
            if (!v2) break;
            return send(MessageType::TableInfo32, encodeTableInfo32(tableInfo()));
        case MessageType::ReadDeviceInfo:
            if (!v2) break;
            return send(MessageType::DeviceInfo,
                        encodeDeviceInfo({static_cast<std::uint8_t>(m_protocol), static_cast<std::uint8_t>(kAdcBits),
                                          static_cast<std::uint32_t>(kMaxTableBytes32)}));
        case MessageType::TableBegin: {
            const auto begin = decodeTableBegin(frame.payload);
            if (!begin) return ack(cmd, AckResult::BadLength);
            m_uploadCrc16 = begin->crc;
            m_uploadCrc32.reset();
            return handleBegin(cmd, begin->version, begin->sizeBytes, kMaxTableBytes);
        }
        case MessageType::TableBegin32: {
            if (!v2) break;
            const auto begin = decodeTableBegin32(frame.payload);
            if (!begin) return ack(cmd, AckResult::BadLength);
            m_uploadCrc16.reset();
            m_uploadCrc32 = begin->crc32c;
            return handleBegin(cmd, begin->version, begin->sizeBytes, kMaxTableBytes32);
        }
        case MessageType::TableChunk:
            return handleChunk(frame);
        case MessageType::TableCommit:
            return handleCommit(cmd);
        case MessageType::Sample:
        case MessageType::Ack:
        case MessageType::TableInfo:
        case MessageType::TableInfo32:
        case MessageType::DeviceInfo:
            break;
    }
    return ack(cmd, AckResult::UnknownCommand);
}

std::vector<std::uint8_t> MandrelEmulator::handleBegin(std::uint8_t command, std::uint16_t version,
                                                       std::uint32_t sizeBytes, std::size_t maxBytes) {
    if (sizeBytes == 0 || sizeBytes > maxBytes) {
        m_uploading = false;
        return ack(command, AckResult::BadArgument);
    }
    m_uploading = true;
    m_uploadVersion = version;
    m_uploadSize = sizeBytes;
    m_pending.clear();
    m_pending.reserve(sizeBytes);
    return ack(command, AckResult::Ok, 0);
}

std::vector<std::uint8_t> MandrelEmulator::handleChunk(const Frame& frame) {
    const std::uint8_t cmd = frame.type;
    const auto chunk = decodeTableChunk(frame.payload);
    if (!chunk) return ack(cmd, AckResult::BadLength);
    const auto received = static_cast<std::uint32_t>(m_pending.size());
    if (!m_uploading) return ack(cmd, AckResult::NoUpload, received);
    const auto size = static_cast<std::uint32_t>(chunk->bytes.size());
    if (chunk->offset + size == received && chunk->offset <= received)  // the last chunk again
        return ack(cmd, AckResult::Ok, received);
    if (chunk->offset != received) return ack(cmd, AckResult::OutOfOrder, received);
    if (received + size > m_uploadSize) return ack(cmd, AckResult::BadArgument, received);
    m_pending.insert(m_pending.end(), chunk->bytes.begin(), chunk->bytes.end());
    return ack(cmd, AckResult::Ok, static_cast<std::uint32_t>(m_pending.size()));
}

std::vector<std::uint8_t> MandrelEmulator::handleCommit(std::uint8_t command) {
    if (!m_uploading) return ack(command, AckResult::NoUpload);
    m_uploading = false;
    if (m_pending.size() != m_uploadSize) return ack(command, AckResult::BadLength);
    const bool crcMatches =
        m_uploadCrc32 ? core::crc32c(m_pending) == *m_uploadCrc32 : core::crc16Ccitt(m_pending) == *m_uploadCrc16;
    if (!crcMatches) return ack(command, AckResult::CrcMismatch);
    std::vector<std::uint8_t> flash = std::move(m_pending);
    m_pending.clear();
    if (m_faultyFlash) flash[flash.size() / 2] ^= 0x01;
    store(std::move(flash), m_uploadVersion);
    return ack(command, AckResult::Ok);
}

SamplePayload MandrelEmulator::makeSample(double timeS) {
    if (m_stuck && m_haveLast) {
        SamplePayload s = m_last;
        s.timeUs = static_cast<std::uint32_t>(std::llround(timeS * 1e6));
        return s;
    }
    std::array<double, 2> d = m_source(timeS);
    for (double& v : d) {
        if (m_noiseMm > 0.0) {
            m_noiseState = m_noiseState * 1664525u + 1013904223u;  // LCG (Numerical Recipes)
            v += m_noiseMm * ((m_noiseState >> 8) / 16777216.0 * 2.0 - 1.0);
        }
    }
    SamplePayload s;
    s.timeUs = static_cast<std::uint32_t>(std::llround(timeS * 1e6));
    s.status = kStatusStreaming;
    if (m_tableValid) s.status |= kStatusTableValid;
    for (std::size_t plane = 0; plane < 2; ++plane) {
        s.adcCode[plane] = adcCode(d[plane]);
        if (s.adcCode[plane] == 0 || s.adcCode[plane] == kMaxCode)
            s.status |= plane == 0 ? kStatusOverrangePlane1 : kStatusOverrangePlane2;
        s.deflectionNm[plane] = m_tableValid ? static_cast<std::int32_t>(std::llround(d[plane] * 1e6)) : 0;
    }
    m_last = s;
    m_haveLast = true;
    return s;
}

std::vector<std::uint8_t> MandrelEmulator::advance(double dtS) {
    m_timeS += std::max(0.0, dtS);
    std::vector<std::uint8_t> out;
    if (!m_streaming) return out;
    const double period = 1.0 / m_rateHz;
    // At most one second of samples per call, so a long pause never floods the line.
    if (m_timeS - m_nextSampleS > 1.0) m_nextSampleS = m_timeS - 1.0;
    while (m_nextSampleS <= m_timeS) {
        const auto frame = send(MessageType::Sample, encodeSample(makeSample(m_nextSampleS)));
        out.insert(out.end(), frame.begin(), frame.end());
        m_nextSampleS += period;
    }
    return out;
}

}  // namespace tt::devices
