#include "devices/simulator/mandrel_emulator.h"

#include <algorithm>
#include <cmath>

#include "core/common/crc16.h"

namespace tt::devices {

using namespace probe;

MandrelEmulator::MandrelEmulator() {
    m_source = [](double) { return std::array<double, 2>{0.020, -0.005}; };
}

void MandrelEmulator::setDeflectionSource(std::function<std::array<double, 2>(double)> source) {
    if (source) m_source = std::move(source);
}

std::int32_t MandrelEmulator::adcCode(double deflectionMm) {
    const double code = kMidCode + kCountsPerMm * deflectionMm + kCubicCountsPerMm3 * std::pow(deflectionMm, 3);
    return static_cast<std::int32_t>(std::clamp(std::round(code), 0.0, static_cast<double>(kMaxCode)));
}

void MandrelEmulator::preloadTable(std::vector<std::uint8_t> image, std::uint16_t version) {
    m_table = std::move(image);
    m_tableVersion = version;
    m_tableCrc = core::crc16Ccitt(m_table);
    m_tableValid = !m_table.empty();
}

TableInfoPayload MandrelEmulator::tableInfo() const {
    return {m_tableVersion, m_tableCrc, static_cast<std::uint32_t>(m_table.size()), m_tableValid};
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
        case MessageType::TableBegin: {
            const auto begin = decodeTableBegin(frame.payload);
            if (!begin) return ack(cmd, AckResult::BadLength);
            if (begin->sizeBytes == 0 || begin->sizeBytes > kMaxTableBytes) return ack(cmd, AckResult::BadArgument);
            m_uploading = true;
            m_upload = begin.value();
            m_pending.clear();
            return ack(cmd, AckResult::Ok, 0);
        }
        case MessageType::TableChunk: {
            const auto chunk = decodeTableChunk(frame.payload);
            if (!chunk) return ack(cmd, AckResult::BadLength);
            const auto received = static_cast<std::uint32_t>(m_pending.size());
            if (!m_uploading) return ack(cmd, AckResult::NoUpload, received);
            const auto size = static_cast<std::uint32_t>(chunk->bytes.size());
            if (chunk->offset + size == received && chunk->offset <= received)  // the last chunk again
                return ack(cmd, AckResult::Ok, received);
            if (chunk->offset != received) return ack(cmd, AckResult::OutOfOrder, received);
            if (received + size > m_upload.sizeBytes) return ack(cmd, AckResult::BadArgument, received);
            m_pending.insert(m_pending.end(), chunk->bytes.begin(), chunk->bytes.end());
            return ack(cmd, AckResult::Ok, static_cast<std::uint32_t>(m_pending.size()));
        }
        case MessageType::TableCommit: {
            if (!m_uploading) return ack(cmd, AckResult::NoUpload);
            m_uploading = false;
            if (m_pending.size() != m_upload.sizeBytes) return ack(cmd, AckResult::BadLength);
            if (core::crc16Ccitt(m_pending) != m_upload.crc) return ack(cmd, AckResult::CrcMismatch);
            m_table = m_pending;
            if (m_faultyFlash) m_table[m_table.size() / 2] ^= 0x01;
            m_tableVersion = m_upload.version;
            m_tableCrc = core::crc16Ccitt(m_table);  // what the flash really holds
            m_tableValid = true;
            return ack(cmd, AckResult::Ok);
        }
        case MessageType::Sample:
        case MessageType::Ack:
        case MessageType::TableInfo:
            break;
    }
    return ack(cmd, AckResult::UnknownCommand);
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
