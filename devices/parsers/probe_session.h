#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/ports/deflection_probe.h"
#include "devices/parsers/probe_protocol.h"

namespace tt::devices::probe {

/// Timing of a probe session.
struct SessionConfig {
    int rateHz = 200;              ///< sample rate asked of the mandrel, Hz (1..1000)
    double silenceTimeoutS = 0.5;  ///< no frame for this long while streaming: the link is silent
    double replyTimeoutS = 0.3;    ///< a command without its reply for this long is sent again
    int maxTries = 3;              ///< sends of one command before giving up
    double restartAfterS = 1.0;    ///< after giving up, start the handshake again this much later
};

/// The host side of the probe-mandrel protocol, independent of the wire: the handshake (ask
/// what the mandrel is, which tells protocol 2 from protocol 1; read the table info, set the
/// rate, start streaming), one command in flight at a time with
/// timeouts and resends, decoding of samples (lost, duplicated, corrupt frames never used; an
/// over-range or excitation-fault sample is counted and dropped), the silence watchdog, and
/// table uploads (TableUploader). The caller moves bytes: poll() gives what to send, receive()
/// takes what arrived; both take the current time. Pure C++ (the serial plugin and the
/// simulator's probe share it).
class ProbeSession {
public:
    enum class Link {
        Idle,       ///< not started, or stopped
        Handshake,  ///< asking what the mandrel is, reading the table, setting the rate, starting the stream
        Streaming,  ///< samples arrive
        Silent,     ///< streaming but nothing arrived for silenceTimeoutS
        Failed,     ///< a command got no reply after maxTries; restarts after restartAfterS
    };

    /// Upload progress for the operator.
    struct UploadState {
        bool active = false;  ///< an upload was started and has not finished
        std::optional<TableUploader::Phase> phase;
        double progress = 0.0;
        std::string message;
    };

    explicit ProbeSession(SessionConfig config = {});

    /// The wire is (re)opened: forget partial frames and start the handshake.
    void start(double nowS);
    /// Asks the mandrel to stop streaming; the link goes idle.
    void stop(double nowS);
    /// Bytes from the mandrel, arrived at `nowS`.
    void receive(std::span<const std::uint8_t> bytes, double nowS);
    /// Bytes to send now (the next command, or a resend); also runs the watchdogs.
    std::vector<std::uint8_t> poll(double nowS);
    /// Samples received since the last call, oldest first, stamped with their arrival time.
    std::vector<core::ProbeSample> takeSamples();
    /// The last sample, for display.
    const std::optional<SamplePayload>& lastSample() const { return m_lastSample; }

    Link link() const { return m_link; }
    /// The current problem in the user's terms (silence, no answer); empty when streaming.
    const std::string& problem() const { return m_problem; }
    /// The last problem with a frame or a sample (corrupt, refused command), kept.
    const std::string& lastError() const { return m_lastError; }
    const std::optional<TableInfoPayload>& tableInfo() const { return m_tableInfo; }
    /// Queues READ_TABLE_INFO, or READ_TABLE_INFO_32 for a protocol-2 mandrel (e.g. for Test
    /// connection).
    void requestTableInfo();
    /// The mandrel's DEVICE_INFO (protocol 2); nullopt before it answered or for protocol 1.
    const std::optional<DeviceInfoPayload>& deviceInfo() const { return m_deviceInfo; }
    /// The mandrel's protocol as far as known (nullopt until the handshake found out).
    const std::optional<MandrelCapabilities>& mandrel() const { return m_mandrel; }

    /// Starts uploading a linearisation table, `crc32c` = CRC-32C of the whole image (see
    /// TableUploader; throws std::invalid_argument for an empty, oversized or corrupt image, or
    /// std::logic_error while one is running). The upload runs when the handshake has found the
    /// mandrel's protocol.
    void uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c);
    UploadState uploadState() const;

    const FrameStats& frameStats() const { return m_reader.stats(); }
    std::uint64_t samplesUsed() const { return m_samplesUsed; }
    std::uint64_t samplesDropped() const { return m_samplesDropped; }  ///< over-range, excitation fault
    std::uint64_t badMessages() const { return m_badMessages; }        ///< valid frame, invalid payload
    std::uint64_t resends() const { return m_resends; }

private:
    struct Pending {
        MessageType type;
        std::vector<std::uint8_t> payload;
    };
    void handleFrame(const Frame& frame, double nowS);
    void handleSample(const Frame& frame, double nowS);
    void handleAck(const AckPayload& ack);
    void handleTableInfo(const TableInfoPayload& info);
    void handleDeviceInfo(const DeviceInfoPayload& info);
    void learnMandrel(const MandrelCapabilities& mandrel);
    /// Decodes a reply payload; counts and records a bad one.
    template <typename T>
    std::optional<T> decoded(const ParseResult<T>& result);
    void finishCommand();
    std::vector<std::uint8_t> sendCommand(const Pending& command, double nowS);
    void giveUp(double nowS);

    SessionConfig m_config;
    FrameReader m_reader;
    std::uint8_t m_sequence = 0;
    Link m_link = Link::Idle;
    std::string m_problem;
    std::string m_lastError;
    std::deque<Pending> m_queue;
    std::optional<Pending> m_outstanding;
    int m_tries = 0;
    double m_deadlineS = 0.0;
    double m_lastFrameS = 0.0;
    double m_restartAtS = 0.0;
    bool m_streamingWanted = false;
    std::optional<TableInfoPayload> m_tableInfo;
    std::optional<DeviceInfoPayload> m_deviceInfo;
    std::optional<MandrelCapabilities> m_mandrel;
    std::optional<SamplePayload> m_lastSample;
    std::vector<core::ProbeSample> m_samples;
    std::optional<TableUploader> m_uploader;
    std::string m_uploadMessage;
    std::uint64_t m_samplesUsed = 0;
    std::uint64_t m_samplesDropped = 0;
    std::uint64_t m_badMessages = 0;
    std::uint64_t m_resends = 0;
    std::uint64_t m_badFramesReported = 0;
};

/// Printable name of a link state ("streaming").
std::string_view linkName(ProbeSession::Link link);

}  // namespace tt::devices::probe
