#include "devices/parsers/probe_protocol.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"
#include "devices/parsers/byte_codec.h"

namespace tt::devices::probe {

namespace {

std::string hex16(std::uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%04X", v);
    return text;
}

std::string hex32(std::uint32_t v) {
    char text[12];
    std::snprintf(text, sizeof text, "0x%08X", static_cast<unsigned>(v));
    return text;
}

template <typename T>
ParseResult<T> wrongLength(std::string_view what, std::size_t got, std::string_view expected) {
    return ParseResult<T>::failure(std::string(what) + " payload has " + std::to_string(got) + " bytes, expected " +
                                   std::string(expected));
}

}  // namespace

std::string messageTypeName(std::uint8_t type) {
    switch (static_cast<MessageType>(type)) {
        case MessageType::Sample:
            return "SAMPLE";
        case MessageType::Ack:
            return "ACK";
        case MessageType::TableInfo:
            return "TABLE_INFO";
        case MessageType::DeviceInfo:
            return "DEVICE_INFO";
        case MessageType::TableInfo32:
            return "TABLE_INFO_32";
        case MessageType::StartStream:
            return "START_STREAM";
        case MessageType::StopStream:
            return "STOP_STREAM";
        case MessageType::SetRate:
            return "SET_RATE";
        case MessageType::ReadTableInfo:
            return "READ_TABLE_INFO";
        case MessageType::TableBegin:
            return "TABLE_BEGIN";
        case MessageType::TableChunk:
            return "TABLE_CHUNK";
        case MessageType::TableCommit:
            return "TABLE_COMMIT";
        case MessageType::ReadDeviceInfo:
            return "READ_DEVICE_INFO";
        case MessageType::TableBegin32:
            return "TABLE_BEGIN_32";
        case MessageType::ReadTableInfo32:
            return "READ_TABLE_INFO_32";
    }
    char text[16];
    std::snprintf(text, sizeof text, "type 0x%02X", type);
    return text;
}

std::string_view ackResultName(AckResult result) {
    switch (result) {
        case AckResult::Ok:
            return "ok";
        case AckResult::BadLength:
            return "wrong payload length";
        case AckResult::BadArgument:
            return "value out of range";
        case AckResult::OutOfOrder:
            return "chunk out of order";
        case AckResult::NoUpload:
            return "no upload in progress";
        case AckResult::CrcMismatch:
            return "CRC mismatch";
        case AckResult::UnknownCommand:
            return "unknown command";
        case AckResult::Busy:
            return "busy";
    }
    return "unknown result";
}

std::vector<std::uint8_t> encodeFrame(std::uint8_t sequence, std::uint8_t type, std::span<const std::uint8_t> payload) {
    if (payload.size() > kMaxPayload)
        throw std::invalid_argument("probe frame: payload of " + std::to_string(payload.size()) +
                                    " bytes exceeds the 250-byte limit");
    std::vector<std::uint8_t> frame;
    frame.reserve(kHeaderBytes + payload.size() + kCrcBytes);
    frame.push_back(kSync);
    frame.push_back(static_cast<std::uint8_t>(payload.size()));
    frame.push_back(sequence);
    frame.push_back(type);
    frame.insert(frame.end(), payload.begin(), payload.end());
    const std::uint16_t crc = core::crc16Ccitt(std::span(frame).subspan(1));
    frame.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    frame.push_back(static_cast<std::uint8_t>(crc >> 8));
    return frame;
}

std::vector<std::uint8_t> encodeSample(const SamplePayload& sample) {
    ByteWriter w;
    w.u32(sample.timeUs);
    w.i32(sample.adcCode[0]);
    w.i32(sample.adcCode[1]);
    w.i32(sample.deflectionNm[0]);
    w.i32(sample.deflectionNm[1]);
    w.u16(sample.status);
    return w.take();
}

ParseResult<SamplePayload> decodeSample(std::span<const std::uint8_t> payload) {
    if (payload.size() != kSamplePayloadBytes) return wrongLength<SamplePayload>("SAMPLE", payload.size(), "22");
    ByteReader r(payload);
    SamplePayload s;
    s.timeUs = r.u32();
    s.adcCode[0] = r.i32();
    s.adcCode[1] = r.i32();
    s.deflectionNm[0] = r.i32();
    s.deflectionNm[1] = r.i32();
    s.status = r.u16();
    return ParseResult<SamplePayload>::success(s);
}

std::vector<std::uint8_t> encodeAck(const AckPayload& ack) {
    ByteWriter w;
    w.u8(ack.command);
    w.u8(static_cast<std::uint8_t>(ack.result));
    w.u32(ack.detail);
    return w.take();
}

ParseResult<AckPayload> decodeAck(std::span<const std::uint8_t> payload) {
    if (payload.size() != 6) return wrongLength<AckPayload>("ACK", payload.size(), "6");
    ByteReader r(payload);
    AckPayload ack;
    ack.command = r.u8();
    const std::uint8_t result = r.u8();
    if (result > static_cast<std::uint8_t>(AckResult::Busy))
        return ParseResult<AckPayload>::failure("ACK has unknown result code " + std::to_string(result));
    ack.result = static_cast<AckResult>(result);
    ack.detail = r.u32();
    return ParseResult<AckPayload>::success(ack);
}

std::vector<std::uint8_t> encodeTableInfo(const TableInfoPayload& info) {
    ByteWriter w;
    w.u16(info.version);
    w.u16(info.crc);
    w.u32(info.sizeBytes);
    w.u8(info.valid ? 1 : 0);
    return w.take();
}

ParseResult<TableInfoPayload> decodeTableInfo(std::span<const std::uint8_t> payload) {
    if (payload.size() != kTableInfoPayloadBytes)
        return wrongLength<TableInfoPayload>("TABLE_INFO", payload.size(), "9");
    ByteReader r(payload);
    TableInfoPayload info;
    info.version = r.u16();
    info.crc = r.u16();
    info.sizeBytes = r.u32();
    const std::uint8_t flags = r.u8();
    if (flags > 1)
        return ParseResult<TableInfoPayload>::failure("TABLE_INFO has unknown flags " + std::to_string(flags));
    info.valid = flags == 1;
    return ParseResult<TableInfoPayload>::success(info);
}

std::vector<std::uint8_t> encodeTableInfo32(const TableInfoPayload& info) {
    if (!info.crc32c) throw std::invalid_argument("TABLE_INFO_32 needs the CRC-32C of the stored image");
    ByteWriter w;
    w.u16(info.version);
    w.u32(*info.crc32c);
    w.u16(info.crc);
    w.u32(info.sizeBytes);
    w.u8(info.valid ? 1 : 0);
    return w.take();
}

ParseResult<TableInfoPayload> decodeTableInfo32(std::span<const std::uint8_t> payload) {
    if (payload.size() != kTableInfo32PayloadBytes)
        return wrongLength<TableInfoPayload>("TABLE_INFO_32", payload.size(), "13");
    ByteReader r(payload);
    TableInfoPayload info;
    info.version = r.u16();
    info.crc32c = r.u32();
    info.crc = r.u16();
    info.sizeBytes = r.u32();
    const std::uint8_t flags = r.u8();
    if (flags > 1)
        return ParseResult<TableInfoPayload>::failure("TABLE_INFO_32 has unknown flags " + std::to_string(flags));
    info.valid = flags == 1;
    return ParseResult<TableInfoPayload>::success(info);
}

std::vector<std::uint8_t> encodeDeviceInfo(const DeviceInfoPayload& info) {
    ByteWriter w;
    w.u8(info.protocol);
    w.u8(info.adcBits);
    w.u32(info.maxTableBytes);
    return w.take();
}

ParseResult<DeviceInfoPayload> decodeDeviceInfo(std::span<const std::uint8_t> payload) {
    if (payload.size() != kDeviceInfoPayloadBytes)
        return wrongLength<DeviceInfoPayload>("DEVICE_INFO", payload.size(), "6");
    ByteReader r(payload);
    DeviceInfoPayload info;
    info.protocol = r.u8();
    info.adcBits = r.u8();
    info.maxTableBytes = r.u32();
    if (info.protocol < 2)
        return ParseResult<DeviceInfoPayload>::failure("DEVICE_INFO names protocol " + std::to_string(info.protocol) +
                                                       "; it exists from protocol 2 on");
    if (info.adcBits < 8 || info.adcBits > 24)
        return ParseResult<DeviceInfoPayload>::failure("DEVICE_INFO gives an ADC of " + std::to_string(info.adcBits) +
                                                       " bits, outside 8 .. 24");
    if (info.maxTableBytes == 0)
        return ParseResult<DeviceInfoPayload>::failure("DEVICE_INFO says the mandrel stores no table");
    return ParseResult<DeviceInfoPayload>::success(info);
}

MandrelCapabilities MandrelCapabilities::from(const DeviceInfoPayload& info) {
    return {info.protocol, std::min<std::size_t>(info.maxTableBytes, kMaxTableBytes32)};
}

std::vector<std::uint8_t> encodeTableBegin(const TableBeginPayload& begin) {
    ByteWriter w;
    w.u16(begin.version);
    w.u16(begin.crc);
    w.u32(begin.sizeBytes);
    return w.take();
}

ParseResult<TableBeginPayload> decodeTableBegin(std::span<const std::uint8_t> payload) {
    if (payload.size() != 8) return wrongLength<TableBeginPayload>("TABLE_BEGIN", payload.size(), "8");
    ByteReader r(payload);
    TableBeginPayload b;
    b.version = r.u16();
    b.crc = r.u16();
    b.sizeBytes = r.u32();
    return ParseResult<TableBeginPayload>::success(b);
}

std::vector<std::uint8_t> encodeTableBegin32(const TableBegin32Payload& begin) {
    ByteWriter w;
    w.u16(begin.version);
    w.u32(begin.crc32c);
    w.u32(begin.sizeBytes);
    return w.take();
}

ParseResult<TableBegin32Payload> decodeTableBegin32(std::span<const std::uint8_t> payload) {
    if (payload.size() != kTableBegin32PayloadBytes)
        return wrongLength<TableBegin32Payload>("TABLE_BEGIN_32", payload.size(), "10");
    ByteReader r(payload);
    TableBegin32Payload b;
    b.version = r.u16();
    b.crc32c = r.u32();
    b.sizeBytes = r.u32();
    return ParseResult<TableBegin32Payload>::success(b);
}

std::vector<std::uint8_t> encodeTableChunk(const TableChunkPayload& chunk) {
    if (chunk.bytes.empty() || chunk.bytes.size() > kMaxChunkBytes)
        throw std::invalid_argument("probe table chunk must hold 1 to 128 bytes");
    ByteWriter w;
    w.u32(chunk.offset);
    w.bytes(chunk.bytes);
    return w.take();
}

ParseResult<TableChunkPayload> decodeTableChunk(std::span<const std::uint8_t> payload) {
    if (payload.size() < 5 || payload.size() > 4 + kMaxChunkBytes)
        return wrongLength<TableChunkPayload>("TABLE_CHUNK", payload.size(), "5 to 132");
    ByteReader r(payload);
    TableChunkPayload c;
    c.offset = r.u32();
    const auto rest = r.rest();
    c.bytes.assign(rest.begin(), rest.end());
    return ParseResult<TableChunkPayload>::success(std::move(c));
}

std::vector<std::uint8_t> encodeRate(int rateHz) {
    if (rateHz < kMinRateHz || rateHz > kMaxRateHz)
        throw std::invalid_argument("probe sample rate " + std::to_string(rateHz) + " Hz is outside 1 to 1000 Hz");
    ByteWriter w;
    w.u16(static_cast<std::uint16_t>(rateHz));
    return w.take();
}

ParseResult<int> decodeRate(std::span<const std::uint8_t> payload) {
    if (payload.size() != 2) return wrongLength<int>("SET_RATE", payload.size(), "2");
    ByteReader r(payload);
    const int rate = r.u16();
    if (rate < kMinRateHz || rate > kMaxRateHz)
        return ParseResult<int>::failure("sample rate " + std::to_string(rate) + " Hz is outside 1 to 1000 Hz");
    return ParseResult<int>::success(rate);
}

// ---- FrameReader ----

bool FrameReader::acceptSequence(std::uint8_t sequence) {
    if (!m_haveSequence) {
        m_haveSequence = true;
        m_lastSequence = sequence;
        return true;
    }
    if (sequence == m_lastSequence) {
        ++m_stats.duplicate;
        return false;
    }
    const auto gap = static_cast<std::uint8_t>(sequence - static_cast<std::uint8_t>(m_lastSequence + 1));
    if (gap < 128) {
        m_stats.lost += gap;
        m_lastSequence = sequence;
        m_staleInARow = 0;
        return true;
    }
    // Older than the last frame: a late duplicate, unless the mandrel restarted its count.
    if (++m_staleInARow < 3) {
        ++m_stats.duplicate;
        return false;
    }
    ++m_stats.resyncs;
    m_staleInARow = 0;
    m_lastSequence = sequence;
    return true;
}

std::vector<Frame> FrameReader::feed(std::span<const std::uint8_t> bytes) {
    m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
    std::vector<Frame> frames;
    std::size_t pos = 0;
    while (pos < m_buffer.size()) {
        if (m_buffer[pos] != kSync) {
            ++pos;
            ++m_stats.discardedBytes;
            continue;
        }
        if (m_buffer.size() - pos < kHeaderBytes) break;
        const std::size_t length = m_buffer[pos + 1];
        const std::uint64_t at = m_consumed + pos;  // position in the whole stream
        if (length > kMaxPayload) {
            if (at >= m_badUntil) ++m_stats.malformed;  // not a false SYNC inside a frame already counted
            ++m_stats.discardedBytes;
            ++pos;
            continue;
        }
        const std::size_t total = kHeaderBytes + length + kCrcBytes;
        if (m_buffer.size() - pos < total) break;
        const std::span<const std::uint8_t> covered(m_buffer.data() + pos + 1, kHeaderBytes - 1 + length);
        const std::uint16_t expected = core::crc16Ccitt(covered);
        const std::uint16_t received =
            static_cast<std::uint16_t>(m_buffer[pos + total - 2] | (m_buffer[pos + total - 1] << 8));
        if (expected != received) {
            // Count each corrupt frame once: a SYNC value inside a frame already found corrupt is
            // a false start, discarded but not counted again.
            if (at >= m_badUntil) {
                ++m_stats.corrupt;
                m_badUntil = at + total;
            }
            ++m_stats.discardedBytes;
            ++pos;
            continue;
        }
        const std::uint8_t sequence = m_buffer[pos + 2];
        if (acceptSequence(sequence)) {
            Frame frame;
            frame.sequence = sequence;
            frame.type = m_buffer[pos + 3];
            frame.payload.assign(m_buffer.begin() + static_cast<std::ptrdiff_t>(pos + kHeaderBytes),
                                 m_buffer.begin() + static_cast<std::ptrdiff_t>(pos + kHeaderBytes + length));
            frames.push_back(std::move(frame));
            ++m_stats.frames;
        }
        pos += total;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(pos));
    m_consumed += pos;
    return frames;
}

void FrameReader::reset() {
    m_consumed += m_buffer.size();
    m_buffer.clear();
    m_haveSequence = false;
    m_staleInARow = 0;
}

// ---- TableUploader ----

namespace {

std::string tooLarge(std::size_t size, const MandrelCapabilities& mandrel) {
    std::string text = "linearisation table upload: the image has " + std::to_string(size) + " bytes; the mandrel";
    if (mandrel.protocol < 2)
        return text + " speaks probe protocol 1, which stores at most 65536 bytes (tables of up to 14 bits); a " +
               "table of 15 or 16 bits needs mandrel firmware of protocol 2";
    return text + " stores at most " + std::to_string(mandrel.maxTableBytes);
}

}  // namespace

TableUploader::TableUploader(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c,
                             const MandrelCapabilities& mandrel, std::size_t chunkBytes)
    : m_image(std::move(image)),
      m_version(version),
      m_crc32c(crc32c),
      m_crc16(0),
      m_mandrel(mandrel),
      m_chunkBytes(chunkBytes) {
    if (m_image.empty()) throw std::invalid_argument("linearisation table upload: the table image is empty");
    if (m_image.size() > m_mandrel.maxTableBytes) throw std::invalid_argument(tooLarge(m_image.size(), m_mandrel));
    if (m_chunkBytes == 0 || m_chunkBytes > kMaxChunkBytes)
        throw std::invalid_argument("linearisation table upload: chunks must hold 1 to 128 bytes");
    const std::uint32_t actual = core::crc32c(m_image);
    if (actual != m_crc32c)
        throw std::invalid_argument("linearisation table upload: the image's CRC-32C is " + hex32(actual) +
                                    ", not the stated " + hex32(m_crc32c) + "; the image is corrupt");
    m_crc16 = core::crc16Ccitt(m_image);
    m_chunkCount = (m_image.size() + m_chunkBytes - 1) / m_chunkBytes;
}

void TableUploader::setMandrel(const MandrelCapabilities& mandrel) {
    if (m_phase != Phase::Begin) return;
    m_mandrel = mandrel;
    if (m_image.size() > m_mandrel.maxTableBytes) fail(tooLarge(m_image.size(), m_mandrel));
}

TableUploader::Command TableUploader::current() const {
    const bool wide = m_mandrel.protocol >= 2;
    switch (m_phase) {
        case Phase::Begin:
            if (wide)
                return {MessageType::TableBegin32,
                        encodeTableBegin32({m_version, m_crc32c, static_cast<std::uint32_t>(m_image.size())})};
            return {MessageType::TableBegin,
                    encodeTableBegin({m_version, m_crc16, static_cast<std::uint32_t>(m_image.size())})};
        case Phase::Chunks: {
            const std::size_t offset = m_nextChunk * m_chunkBytes;
            const std::size_t size = std::min(m_chunkBytes, m_image.size() - offset);
            TableChunkPayload chunk;
            chunk.offset = static_cast<std::uint32_t>(offset);
            chunk.bytes.assign(m_image.begin() + static_cast<std::ptrdiff_t>(offset),
                               m_image.begin() + static_cast<std::ptrdiff_t>(offset + size));
            return {MessageType::TableChunk, encodeTableChunk(chunk)};
        }
        case Phase::Commit:
            return {MessageType::TableCommit, {}};
        case Phase::Verify:
            return {wide ? MessageType::ReadTableInfo32 : MessageType::ReadTableInfo, {}};
        case Phase::Done:
        case Phase::Failed:
            break;
    }
    throw std::logic_error("linearisation table upload: no command once the upload has finished");
}

void TableUploader::onAck(const AckPayload& ack) {
    if (finished() || m_phase == Phase::Verify) return;
    if (ack.command != static_cast<std::uint8_t>(current().type)) return;
    if (m_phase == Phase::Commit && ack.result == AckResult::NoUpload) {
        // The ACK of our first COMMIT was lost and the resent COMMIT found nothing pending:
        // whether the table was stored is what the verification step finds out.
        m_phase = Phase::Verify;
        return;
    }
    if (ack.result != AckResult::Ok) {
        fail("the mandrel refused " + messageTypeName(ack.command) + ": " + std::string(ackResultName(ack.result)));
        return;
    }
    switch (m_phase) {
        case Phase::Begin:
            m_phase = Phase::Chunks;
            break;
        case Phase::Chunks: {
            // Advance only on the ACK that confirms this chunk: a late ACK of a resent,
            // earlier chunk reports fewer bytes received and is ignored.
            const std::size_t end = std::min((m_nextChunk + 1) * m_chunkBytes, m_image.size());
            if (ack.detail != end) return;
            if (++m_nextChunk == m_chunkCount) m_phase = Phase::Commit;
            break;
        }
        case Phase::Commit:
            m_phase = Phase::Verify;
            break;
        default:
            break;
    }
}

void TableUploader::onTableInfo(const TableInfoPayload& info) {
    if (m_phase != Phase::Verify) return;
    const bool wide = m_mandrel.protocol >= 2;
    if (wide && !info.crc32c) return;  // a plain TABLE_INFO (e.g. asked for by Test connection): wait for ours
    const bool crcMatches = wide ? *info.crc32c == m_crc32c : info.crc == m_crc16;
    if (!info.valid || info.version != m_version || !crcMatches || info.sizeBytes != m_image.size()) {
        const std::string got = wide ? "CRC-32C " + hex32(*info.crc32c) : "CRC " + hex16(info.crc);
        const std::string expected = wide ? "CRC-32C " + hex32(m_crc32c) : "CRC " + hex16(m_crc16);
        fail("verification failed: the mandrel reports table version " + std::to_string(info.version) + ", " + got +
             ", " + std::to_string(info.sizeBytes) + " bytes" + (info.valid ? "" : " (invalid)") +
             "; expected version " + std::to_string(m_version) + ", " + expected + ", " +
             std::to_string(m_image.size()) + " bytes");
        return;
    }
    m_phase = Phase::Done;
}

void TableUploader::fail(std::string reason) {
    m_failure = std::move(reason);
    m_phase = Phase::Failed;
}

double TableUploader::progress() const {
    const double steps = static_cast<double>(m_chunkCount + 3);
    switch (m_phase) {
        case Phase::Begin:
            return 0.0;
        case Phase::Chunks:
            return static_cast<double>(1 + m_nextChunk) / steps;
        case Phase::Commit:
            return static_cast<double>(1 + m_chunkCount) / steps;
        case Phase::Verify:
            return static_cast<double>(2 + m_chunkCount) / steps;
        case Phase::Done:
            return 1.0;
        case Phase::Failed:
            break;
    }
    return 0.0;
}

std::string_view phaseName(TableUploader::Phase phase) {
    switch (phase) {
        case TableUploader::Phase::Begin:
            return "begin";
        case TableUploader::Phase::Chunks:
            return "chunks";
        case TableUploader::Phase::Commit:
            return "commit";
        case TableUploader::Phase::Verify:
            return "verify";
        case TableUploader::Phase::Done:
            return "done";
        case TableUploader::Phase::Failed:
            return "failed";
    }
    return "unknown";
}

}  // namespace tt::devices::probe
