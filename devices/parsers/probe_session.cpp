#include "devices/parsers/probe_session.h"

#include <cstdio>
#include <stdexcept>

namespace tt::devices::probe {

namespace {

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
}

/// "CRC-32C 0x1A2B3C4D" when the mandrel reported one, else "CRC 0x1A2B".
std::string crcText(const TableInfoPayload& info) {
    char text[32];
    if (info.crc32c)
        std::snprintf(text, sizeof text, "CRC-32C 0x%08X", static_cast<unsigned>(*info.crc32c));
    else
        std::snprintf(text, sizeof text, "CRC 0x%04X", static_cast<unsigned>(info.crc));
    return text;
}

bool isUploadCommand(MessageType type) {
    return type == MessageType::TableBegin || type == MessageType::TableBegin32 || type == MessageType::TableChunk ||
           type == MessageType::TableCommit;
}

}  // namespace

std::string_view linkName(ProbeSession::Link link) {
    switch (link) {
        case ProbeSession::Link::Idle:
            return "idle";
        case ProbeSession::Link::Handshake:
            return "handshake";
        case ProbeSession::Link::Streaming:
            return "streaming";
        case ProbeSession::Link::Silent:
            return "silent";
        case ProbeSession::Link::Failed:
            return "failed";
    }
    return "unknown";
}

ProbeSession::ProbeSession(SessionConfig config) : m_config(config) {
    if (config.rateHz < kMinRateHz || config.rateHz > kMaxRateHz)
        throw std::invalid_argument("probe session: the sample rate must be 1 to 1000 Hz");
    if (!(config.silenceTimeoutS > 0.0) || !(config.replyTimeoutS > 0.0) || config.maxTries < 1 ||
        !(config.restartAfterS > 0.0))
        throw std::invalid_argument("probe session: timeouts must be positive and at least one try allowed");
}

void ProbeSession::start(double nowS) {
    m_reader.reset();
    m_queue.clear();
    m_outstanding.reset();
    m_deviceInfo.reset();
    m_mandrel.reset();  // the mandrel may have been exchanged or re-flashed while the port was closed
    m_queue.push_back({MessageType::ReadDeviceInfo, {}});
    m_queue.push_back({MessageType::ReadTableInfo, {}});
    m_queue.push_back({MessageType::SetRate, encodeRate(m_config.rateHz)});
    m_queue.push_back({MessageType::StartStream, {}});
    m_link = Link::Handshake;
    m_problem.clear();
    m_lastFrameS = nowS;
    m_streamingWanted = true;
    if (m_uploader && !m_uploader->finished())
        m_uploader->fail("the connection to the mandrel was re-opened during the upload; start it again");
}

void ProbeSession::stop(double) {
    m_queue.clear();
    m_outstanding.reset();
    m_queue.push_back({MessageType::StopStream, {}});
    m_streamingWanted = false;
    m_link = Link::Idle;
    m_problem.clear();
}

void ProbeSession::requestTableInfo() {
    m_queue.push_back({MessageType::ReadTableInfo, {}});  // becomes READ_TABLE_INFO_32 for protocol 2 when sent
}

void ProbeSession::uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    if (m_uploader && !m_uploader->finished()) throw std::logic_error("a table upload is already running");
    // Until the handshake has found the mandrel's protocol, assume the newest; the uploader is
    // told before it sends anything (the handshake runs first).
    m_uploader.emplace(std::move(image), version, crc32c, m_mandrel.value_or(MandrelCapabilities{}));
}

ProbeSession::UploadState ProbeSession::uploadState() const {
    UploadState s;
    if (!m_uploader) return s;
    s.active = !m_uploader->finished();
    s.phase = m_uploader->phase();
    s.progress = m_uploader->progress();
    switch (m_uploader->phase()) {
        case TableUploader::Phase::Done:
            s.message =
                "table uploaded and verified" +
                (m_tableInfo ? " (version " + std::to_string(m_tableInfo->version) + ", " + crcText(*m_tableInfo) + ")"
                             : std::string());
            break;
        case TableUploader::Phase::Failed:
            s.message = "table upload failed: " + m_uploader->failure();
            break;
        default:
            s.message = "uploading the table: " + std::string(phaseName(m_uploader->phase()));
            break;
    }
    return s;
}

std::vector<std::uint8_t> ProbeSession::sendCommand(const Pending& command, double nowS) {
    ++m_tries;
    m_deadlineS = nowS + m_config.replyTimeoutS;
    return encodeFrame(m_sequence++, command.type, command.payload);
}

void ProbeSession::giveUp(double nowS) {
    const std::string what = messageTypeName(static_cast<std::uint8_t>(m_outstanding->type));
    m_problem = "the probe mandrel does not answer " + what + " (" + std::to_string(m_config.maxTries) + " tries)";
    if (m_uploader && !m_uploader->finished()) m_uploader->fail(m_problem);
    m_outstanding.reset();
    m_queue.clear();
    m_link = Link::Failed;
    m_restartAtS = nowS + m_config.restartAfterS;
}

std::vector<std::uint8_t> ProbeSession::poll(double nowS) {
    if (m_link == Link::Failed) {
        if (nowS < m_restartAtS) return {};
        start(nowS);
    }
    if (m_outstanding && nowS >= m_deadlineS) {
        if (m_tries >= m_config.maxTries) {
            giveUp(nowS);
            return {};
        }
        ++m_resends;
        return sendCommand(*m_outstanding, nowS);
    }
    std::vector<std::uint8_t> out;
    if (!m_outstanding) {
        if (!m_queue.empty()) {
            m_outstanding = m_queue.front();
            m_queue.pop_front();
            if (m_outstanding->type == MessageType::ReadTableInfo && m_mandrel && m_mandrel->protocol >= 2)
                m_outstanding->type = MessageType::ReadTableInfo32;
        } else if (m_uploader && !m_uploader->finished() && m_link != Link::Idle) {
            const TableUploader::Command c = m_uploader->current();
            m_outstanding = Pending{c.type, c.payload};
        }
        if (m_outstanding) {
            m_tries = 0;
            out = sendCommand(*m_outstanding, nowS);
        }
    }
    if (m_link == Link::Streaming && nowS - m_lastFrameS > m_config.silenceTimeoutS) {
        m_link = Link::Silent;
        m_problem = "no data from the probe mandrel for " + seconds(nowS - m_lastFrameS);
    }
    return out;
}

void ProbeSession::receive(std::span<const std::uint8_t> bytes, double nowS) {
    for (const Frame& frame : m_reader.feed(bytes)) {
        m_lastFrameS = nowS;
        if (m_link == Link::Silent) {
            m_link = Link::Streaming;
            m_problem.clear();
        }
        handleFrame(frame, nowS);
    }
    const FrameStats& st = m_reader.stats();
    if (st.corrupt + st.malformed > m_badFramesReported) {
        m_badFramesReported = st.corrupt + st.malformed;
        m_lastError = "corrupt frames from the probe mandrel (" + std::to_string(m_badFramesReported) +
                      " so far); none of them used";
    }
}

std::vector<core::ProbeSample> ProbeSession::takeSamples() {
    std::vector<core::ProbeSample> out;
    out.swap(m_samples);
    return out;
}

template <typename T>
std::optional<T> ProbeSession::decoded(const ParseResult<T>& result) {
    if (result) return result.value();
    ++m_badMessages;
    m_lastError = result.error();
    return std::nullopt;
}

void ProbeSession::handleFrame(const Frame& frame, double nowS) {
    switch (static_cast<MessageType>(frame.type)) {
        case MessageType::Sample:
            handleSample(frame, nowS);
            return;
        case MessageType::Ack:
            if (const auto ack = decoded(decodeAck(frame.payload))) handleAck(*ack);
            return;
        case MessageType::TableInfo:
            if (const auto info = decoded(decodeTableInfo(frame.payload))) handleTableInfo(*info);
            return;
        case MessageType::TableInfo32:
            if (const auto info = decoded(decodeTableInfo32(frame.payload))) handleTableInfo(*info);
            return;
        case MessageType::DeviceInfo:
            if (const auto info = decoded(decodeDeviceInfo(frame.payload))) handleDeviceInfo(*info);
            return;
        default:
            break;
    }
    ++m_badMessages;
    m_lastError = "unexpected " + messageTypeName(frame.type) + " from the probe mandrel";
}

void ProbeSession::handleSample(const Frame& frame, double nowS) {
    const auto decoded = decodeSample(frame.payload);
    if (!decoded) {
        ++m_badMessages;
        m_lastError = decoded.error();
        return;
    }
    const SamplePayload& s = decoded.value();
    if (s.status & kStatusExcitationFault) {
        ++m_samplesDropped;
        m_lastError = "the probe mandrel reports an excitation fault (bridge supply); sample not used";
        return;
    }
    if (s.status & (kStatusOverrangePlane1 | kStatusOverrangePlane2)) {
        ++m_samplesDropped;
        m_lastError = std::string("the probe mandrel's ADC is over range in plane ") +
                      ((s.status & kStatusOverrangePlane1) ? "1" : "2") + "; sample not used";
        return;
    }
    m_lastSample = s;
    core::ProbeSample sample;
    sample.timeS = nowS;
    sample.adcCode = s.adcCode;
    sample.deflectionMm = {s.deflectionNm[0] * 1e-6, s.deflectionNm[1] * 1e-6};
    sample.linearised = (s.status & kStatusTableValid) != 0;
    m_samples.push_back(sample);
    ++m_samplesUsed;
}

void ProbeSession::finishCommand() {
    m_outstanding.reset();
    m_tries = 0;
}

void ProbeSession::handleAck(const AckPayload& ack) {
    if (!m_outstanding || ack.command != static_cast<std::uint8_t>(m_outstanding->type)) return;  // late ACK
    const MessageType type = m_outstanding->type;
    if (type == MessageType::ReadDeviceInfo) {
        // A protocol-1 mandrel does not know the command: that is the answer, not an error.
        if (ack.result == AckResult::UnknownCommand)
            learnMandrel(MandrelCapabilities::protocol1());
        else
            m_lastError = "the probe mandrel refused READ_DEVICE_INFO: " + std::string(ackResultName(ack.result));
        finishCommand();
        return;
    }
    if (isUploadCommand(type) && m_uploader && !m_uploader->finished()) {
        const auto phaseBefore = m_uploader->phase();
        const double progressBefore = m_uploader->progress();
        m_uploader->onAck(ack);
        if (m_uploader->phase() != phaseBefore || m_uploader->progress() != progressBefore) finishCommand();
        return;
    }
    if (ack.result != AckResult::Ok)
        m_lastError =
            "the probe mandrel refused " + messageTypeName(ack.command) + ": " + std::string(ackResultName(ack.result));
    if (type == MessageType::StartStream && ack.result == AckResult::Ok) {
        m_link = Link::Streaming;
        m_problem.clear();
    }
    finishCommand();
}

void ProbeSession::handleTableInfo(const TableInfoPayload& info) {
    m_tableInfo = info;
    if (m_uploader && m_uploader->phase() == TableUploader::Phase::Verify) m_uploader->onTableInfo(info);
    if (m_outstanding &&
        (m_outstanding->type == MessageType::ReadTableInfo || m_outstanding->type == MessageType::ReadTableInfo32))
        finishCommand();
}

void ProbeSession::handleDeviceInfo(const DeviceInfoPayload& info) {
    m_deviceInfo = info;
    learnMandrel(MandrelCapabilities::from(info));
    if (m_outstanding && m_outstanding->type == MessageType::ReadDeviceInfo) finishCommand();
}

void ProbeSession::learnMandrel(const MandrelCapabilities& mandrel) {
    m_mandrel = mandrel;
    if (m_uploader && !m_uploader->finished()) m_uploader->setMandrel(mandrel);
}

}  // namespace tt::devices::probe
