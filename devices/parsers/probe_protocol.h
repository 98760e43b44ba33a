#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/parsers/parse_result.h"

/// The frame protocol of the probe mandrel's microcontroller (paper 001, way 2: inductive
/// sensor in the boring bar, two bending planes, ADC, linearisation table in the
/// microcontroller). Specified in docs/protocols/probe-mandrel.md; this file is its reference
/// implementation. All multi-byte fields are little-endian.
///
///   offset  size  field
///   0       1     SYNC  = 0xA5
///   1       1     LEN   = payload length, 0..250
///   2       1     SEQ   = sequence number, +1 per frame and direction (mod 256)
///   3       1     TYPE  = message type
///   4       LEN   PAYLOAD
///   4+LEN   2     CRC-16/CCITT-FALSE over LEN, SEQ, TYPE and PAYLOAD (core/common/crc16.h)
namespace tt::devices::probe {

inline constexpr std::uint8_t kSync = 0xA5;
inline constexpr std::size_t kHeaderBytes = 4;
inline constexpr std::size_t kCrcBytes = 2;
inline constexpr std::size_t kMaxPayload = 250;
inline constexpr std::size_t kMaxChunkBytes = 128;        ///< table bytes per TABLE_CHUNK
inline constexpr std::size_t kMaxTableBytes = 64 * 1024;  ///< largest table image the mandrel stores
inline constexpr int kMinRateHz = 1;
inline constexpr int kMaxRateHz = 1000;

/// Message types. 0x01..0x0F travel from the mandrel, 0x10..0x1F from the host.
enum class MessageType : std::uint8_t {
    Sample = 0x01,         ///< mandrel: one measurement (SamplePayload)
    Ack = 0x02,            ///< mandrel: result of a command (AckPayload)
    TableInfo = 0x03,      ///< mandrel: version, CRC and size of the stored table (TableInfoPayload)
    StartStream = 0x10,    ///< host: start sending samples at the set rate
    StopStream = 0x11,     ///< host: stop sending samples
    SetRate = 0x12,        ///< host: u16 sample rate, Hz (1..1000)
    ReadTableInfo = 0x13,  ///< host: ask for TABLE_INFO
    TableBegin = 0x14,     ///< host: start a table upload (TableBeginPayload)
    TableChunk = 0x15,     ///< host: u32 offset + up to 128 table bytes
    TableCommit = 0x16,    ///< host: check the CRC of the received image and store it
};

/// Name of a message type for messages and logs ("SAMPLE"); "type 0x7F" for unknown ones.
std::string messageTypeName(std::uint8_t type);

/// Status bits of a sample.
enum SampleStatus : std::uint16_t {
    kStatusTableValid = 0x0001,       ///< deflection is linearised by a valid table
    kStatusOverrangePlane1 = 0x0002,  ///< ADC of plane 1 at its limit
    kStatusOverrangePlane2 = 0x0004,  ///< ADC of plane 2 at its limit
    kStatusExcitationFault = 0x0008,  ///< bridge supply (20..50 Hz excitation) missing
    kStatusStreaming = 0x0010,        ///< streaming is on
};

/// One measurement of both bending planes.
struct SamplePayload {
    std::uint32_t timeUs = 0;                    ///< mandrel clock, microseconds (wraps)
    std::array<std::int32_t, 2> adcCode{};       ///< raw ADC code per bending plane
    std::array<std::int32_t, 2> deflectionNm{};  ///< linearised deflection per plane, nanometres
    std::uint16_t status = 0;                    ///< SampleStatus bits
};
inline constexpr std::size_t kSamplePayloadBytes = 22;

/// Result codes of ACK.
enum class AckResult : std::uint8_t {
    Ok = 0,
    BadLength = 1,    ///< payload length wrong for the command
    BadArgument = 2,  ///< value out of range (rate, table size)
    OutOfOrder = 3,   ///< chunk offset is not the next expected byte
    NoUpload = 4,     ///< chunk or commit without TABLE_BEGIN
    CrcMismatch = 5,  ///< the received image does not have the announced CRC; old table kept
    UnknownCommand = 6,
    Busy = 7,
};
/// Plain-words name of an ACK result ("CRC mismatch").
std::string_view ackResultName(AckResult result);

/// ACK: which command, the result, and a detail: for TABLE_CHUNK the number of image bytes
/// received so far (the next expected offset), for SET_RATE the rate now in use, else 0.
/// The detail lets the host tell a late ACK of a resent chunk from the ACK of the next one.
struct AckPayload {
    std::uint8_t command = 0;
    AckResult result = AckResult::Ok;
    std::uint32_t detail = 0;
};

/// TABLE_INFO: what the mandrel has stored.
struct TableInfoPayload {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;        ///< CRC-16/CCITT-FALSE of the stored image
    std::uint32_t sizeBytes = 0;  ///< 0 when no table is stored
    bool valid = false;           ///< the stored image passed its CRC check at power-up
};

/// TABLE_BEGIN: the image that will follow.
struct TableBeginPayload {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;
    std::uint32_t sizeBytes = 0;
};

/// TABLE_CHUNK: `bytes` belong at `offset` of the image.
struct TableChunkPayload {
    std::uint32_t offset = 0;
    std::vector<std::uint8_t> bytes;
};

/// A frame that passed the CRC check.
struct Frame {
    std::uint8_t sequence = 0;
    std::uint8_t type = 0;
    std::vector<std::uint8_t> payload;
};

/// Builds the bytes of one frame. Throws std::invalid_argument for a payload over 250 bytes.
std::vector<std::uint8_t> encodeFrame(std::uint8_t sequence, std::uint8_t type, std::span<const std::uint8_t> payload);
inline std::vector<std::uint8_t> encodeFrame(std::uint8_t sequence, MessageType type,
                                             std::span<const std::uint8_t> payload = {}) {
    return encodeFrame(sequence, static_cast<std::uint8_t>(type), payload);
}

std::vector<std::uint8_t> encodeSample(const SamplePayload& sample);
ParseResult<SamplePayload> decodeSample(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeAck(const AckPayload& ack);
ParseResult<AckPayload> decodeAck(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeTableInfo(const TableInfoPayload& info);
ParseResult<TableInfoPayload> decodeTableInfo(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeTableBegin(const TableBeginPayload& begin);
ParseResult<TableBeginPayload> decodeTableBegin(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeTableChunk(const TableChunkPayload& chunk);
ParseResult<TableChunkPayload> decodeTableChunk(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeRate(int rateHz);
ParseResult<int> decodeRate(std::span<const std::uint8_t> payload);

/// Counters of what the frame reader saw. A frame that is lost or corrupt is never returned.
struct FrameStats {
    std::uint64_t frames = 0;          ///< valid frames returned
    std::uint64_t corrupt = 0;         ///< frames failing the CRC check (each counted once)
    std::uint64_t malformed = 0;       ///< impossible length field (> 250)
    std::uint64_t lost = 0;            ///< gaps in the sequence numbers (includes corrupt frames)
    std::uint64_t duplicate = 0;       ///< repeated or older sequence numbers, dropped
    std::uint64_t resyncs = 0;         ///< sequence restarted (e.g. the mandrel was reset)
    std::uint64_t discardedBytes = 0;  ///< bytes outside any valid frame
};

/// Cuts the byte stream from the mandrel into frames: hunts for SYNC, checks the length and
/// the CRC (resynchronising one byte after a bad frame), and checks the sequence number so
/// lost, duplicated and corrupt frames are counted and never used.
class FrameReader {
public:
    /// Appends bytes; returns the valid, new frames in order.
    std::vector<Frame> feed(std::span<const std::uint8_t> bytes);
    /// Forgets buffered bytes and the expected sequence (after reopening the port).
    void reset();
    const FrameStats& stats() const { return m_stats; }

private:
    bool acceptSequence(std::uint8_t sequence);

    std::vector<std::uint8_t> m_buffer;
    std::uint64_t m_consumed = 0;  ///< stream bytes before m_buffer[0]
    std::uint64_t m_badUntil = 0;  ///< stream position where the last corrupt frame ends
    FrameStats m_stats;
    bool m_haveSequence = false;
    std::uint8_t m_lastSequence = 0;
    int m_staleInARow = 0;
};

/// Host side of a linearisation-table upload: BEGIN, the chunks (each acknowledged in turn),
/// COMMIT (the mandrel checks the CRC), then READ_TABLE_INFO to verify that the mandrel reports
/// the new version and CRC. The image is opaque here (its format belongs to core/calibration).
/// The caller sends current(), feeds replies, and resends current() after a timeout.
class TableUploader {
public:
    enum class Phase { Begin, Chunks, Commit, Verify, Done, Failed };

    /// A command to send: type and payload.
    struct Command {
        MessageType type = MessageType::TableBegin;
        std::vector<std::uint8_t> payload;
    };

    /// Throws std::invalid_argument when the image is empty, larger than 64 KiB, or its
    /// CRC-16/CCITT-FALSE is not `crc` (a corrupt image is never sent).
    TableUploader(std::vector<std::uint8_t> image, std::uint16_t version, std::uint16_t crc,
                  std::size_t chunkBytes = kMaxChunkBytes);

    Phase phase() const { return m_phase; }
    bool finished() const { return m_phase == Phase::Done || m_phase == Phase::Failed; }
    /// The command to send now (or to resend after a timeout); only while !finished().
    Command current() const;
    /// Feeds an ACK from the mandrel; ACKs for other commands are ignored.
    void onAck(const AckPayload& ack);
    /// Feeds a TABLE_INFO from the mandrel (used in the Verify phase).
    void onTableInfo(const TableInfoPayload& info);
    /// Marks the upload failed (e.g. too many timeouts).
    void fail(std::string reason);
    /// Fraction of the work done, 0..1.
    double progress() const;
    /// Why it failed; empty otherwise.
    const std::string& failure() const { return m_failure; }
    std::size_t chunkCount() const { return m_chunkCount; }

private:
    std::vector<std::uint8_t> m_image;
    std::uint16_t m_version;
    std::uint16_t m_crc;
    std::size_t m_chunkBytes;
    std::size_t m_chunkCount;
    std::size_t m_nextChunk = 0;
    Phase m_phase = Phase::Begin;
    std::string m_failure;
};

/// Printable name of an uploader phase ("chunks").
std::string_view phaseName(TableUploader::Phase phase);

}  // namespace tt::devices::probe
