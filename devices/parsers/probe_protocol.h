#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
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
inline constexpr std::size_t kMaxChunkBytes = 128;           ///< table bytes per TABLE_CHUNK
inline constexpr std::size_t kMaxTableBytes = 64 * 1024;     ///< largest image of a TABLE_BEGIN (protocol 1)
inline constexpr std::size_t kMaxTableBytes32 = 256 * 1024;  ///< largest image of a TABLE_BEGIN_32 (protocol 2)
inline constexpr int kProtocolVersion = 2;                   ///< the protocol this file implements
inline constexpr int kMinRateHz = 1;
inline constexpr int kMaxRateHz = 1000;

/// Message types. 0x01..0x0F travel from the mandrel, 0x10..0x1F from the host. Protocol 2
/// added 0x04, 0x05 and 0x17..0x19; a protocol-1 mandrel answers those commands with ACK
/// result 6 (unknown command), which is how the host tells the versions apart.
enum class MessageType : std::uint8_t {
    Sample = 0x01,           ///< mandrel: one measurement (SamplePayload)
    Ack = 0x02,              ///< mandrel: result of a command (AckPayload)
    TableInfo = 0x03,        ///< mandrel: version, CRC-16 and size of the stored table (TableInfoPayload)
    DeviceInfo = 0x04,       ///< mandrel (protocol 2): protocol version, ADC bits, largest image (DeviceInfoPayload)
    TableInfo32 = 0x05,      ///< mandrel (protocol 2): TABLE_INFO with the CRC-32C as well (TableInfoPayload)
    StartStream = 0x10,      ///< host: start sending samples at the set rate
    StopStream = 0x11,       ///< host: stop sending samples
    SetRate = 0x12,          ///< host: u16 sample rate, Hz (1..1000)
    ReadTableInfo = 0x13,    ///< host: ask for TABLE_INFO
    TableBegin = 0x14,       ///< host: start a table upload of at most 64 KiB, CRC-16 (TableBeginPayload)
    TableChunk = 0x15,       ///< host: u32 offset + up to 128 table bytes
    TableCommit = 0x16,      ///< host: check the CRC of the received image and store it
    ReadDeviceInfo = 0x17,   ///< host (protocol 2): ask for DEVICE_INFO
    TableBegin32 = 0x18,     ///< host (protocol 2): start an upload of at most 256 KiB, CRC-32C (TableBegin32Payload)
    ReadTableInfo32 = 0x19,  ///< host (protocol 2): ask for TABLE_INFO_32
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

/// TABLE_INFO and TABLE_INFO_32: what the mandrel has stored.
struct TableInfoPayload {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;                ///< CRC-16/CCITT-FALSE of the stored image
    std::uint32_t sizeBytes = 0;          ///< 0 when no table is stored
    bool valid = false;                   ///< the stored image passed its CRC check at power-up
    std::optional<std::uint32_t> crc32c;  ///< CRC-32C of the stored image (TABLE_INFO_32 only)
};
inline constexpr std::size_t kTableInfoPayloadBytes = 9;
inline constexpr std::size_t kTableInfo32PayloadBytes = 13;

/// DEVICE_INFO (protocol 2): what the mandrel is.
struct DeviceInfoPayload {
    std::uint8_t protocol = kProtocolVersion;        ///< protocol version the firmware speaks, >= 2
    std::uint8_t adcBits = 0;                        ///< resolution of its ADC, bits (8..24)
    std::uint32_t maxTableBytes = kMaxTableBytes32;  ///< largest table image it stores, bytes
};
inline constexpr std::size_t kDeviceInfoPayloadBytes = 6;

/// TABLE_BEGIN: the image that will follow (at most 64 KiB, announced with its CRC-16).
struct TableBeginPayload {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;
    std::uint32_t sizeBytes = 0;
};

/// TABLE_BEGIN_32 (protocol 2): the image that will follow (at most 256 KiB, with its CRC-32C).
struct TableBegin32Payload {
    std::uint16_t version = 0;
    std::uint32_t crc32c = 0;
    std::uint32_t sizeBytes = 0;
};
inline constexpr std::size_t kTableBegin32PayloadBytes = 10;

/// What the host knows of a mandrel's protocol: from its DEVICE_INFO, or protocol 1 when it does
/// not know READ_DEVICE_INFO. Decides how a table is uploaded and how large it may be.
struct MandrelCapabilities {
    int protocol = kProtocolVersion;
    std::size_t maxTableBytes = kMaxTableBytes32;

    /// A mandrel of the first protocol: TABLE_BEGIN with CRC-16, images up to 64 KiB.
    static MandrelCapabilities protocol1() { return {1, kMaxTableBytes}; }
    /// From a DEVICE_INFO (the image limit is the smaller of the mandrel's and 256 KiB).
    static MandrelCapabilities from(const DeviceInfoPayload& info);
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
/// TABLE_INFO (9 bytes: u16 version, u16 CRC-16, u32 size, u8 flags); `crc32c` is not sent.
std::vector<std::uint8_t> encodeTableInfo(const TableInfoPayload& info);
ParseResult<TableInfoPayload> decodeTableInfo(std::span<const std::uint8_t> payload);
/// TABLE_INFO_32 (13 bytes: u16 version, u32 CRC-32C, u16 CRC-16, u32 size, u8 flags). Throws
/// std::invalid_argument when `info.crc32c` is empty.
std::vector<std::uint8_t> encodeTableInfo32(const TableInfoPayload& info);
ParseResult<TableInfoPayload> decodeTableInfo32(std::span<const std::uint8_t> payload);
/// DEVICE_INFO (6 bytes: u8 protocol, u8 ADC bits, u32 largest image).
std::vector<std::uint8_t> encodeDeviceInfo(const DeviceInfoPayload& info);
ParseResult<DeviceInfoPayload> decodeDeviceInfo(std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeTableBegin(const TableBeginPayload& begin);
ParseResult<TableBeginPayload> decodeTableBegin(std::span<const std::uint8_t> payload);
/// TABLE_BEGIN_32 (10 bytes: u16 version, u32 CRC-32C, u32 size).
std::vector<std::uint8_t> encodeTableBegin32(const TableBegin32Payload& begin);
ParseResult<TableBegin32Payload> decodeTableBegin32(std::span<const std::uint8_t> payload);
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
/// the new version and CRC. Protocol 2 announces and verifies the CRC-32C of the image
/// (TABLE_BEGIN_32, TABLE_INFO_32; up to 256 KiB); protocol 1 the CRC-16 (TABLE_BEGIN,
/// TABLE_INFO; up to 64 KiB). The image is opaque here (its format belongs to core/calibration).
/// The caller sends current(), feeds replies, and resends current() after a timeout.
class TableUploader {
public:
    enum class Phase { Begin, Chunks, Commit, Verify, Done, Failed };

    /// A command to send: type and payload.
    struct Command {
        MessageType type = MessageType::TableBegin;
        std::vector<std::uint8_t> payload;
    };

    /// `crc32c` is the CRC-32C of the whole image as the caller has it on record. Throws
    /// std::invalid_argument when the image is empty, larger than the mandrel stores, or its
    /// CRC-32C is not `crc32c` (a corrupt image is never sent).
    TableUploader(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c,
                  const MandrelCapabilities& mandrel = {}, std::size_t chunkBytes = kMaxChunkBytes);

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
    /// The mandrel's protocol became known before anything was sent: use it (fails the upload,
    /// saying why, when the image is larger than that mandrel stores). Ignored after BEGIN.
    void setMandrel(const MandrelCapabilities& mandrel);
    const MandrelCapabilities& mandrel() const { return m_mandrel; }
    /// Fraction of the work done, 0..1.
    double progress() const;
    /// Why it failed; empty otherwise.
    const std::string& failure() const { return m_failure; }
    std::size_t chunkCount() const { return m_chunkCount; }

private:
    std::vector<std::uint8_t> m_image;
    std::uint16_t m_version;
    std::uint32_t m_crc32c;
    std::uint16_t m_crc16;
    MandrelCapabilities m_mandrel;
    std::size_t m_chunkBytes;
    std::size_t m_chunkCount;
    std::size_t m_nextChunk = 0;
    Phase m_phase = Phase::Begin;
    std::string m_failure;
};

/// Printable name of an uploader phase ("chunks").
std::string_view phaseName(TableUploader::Phase phase);

}  // namespace tt::devices::probe
