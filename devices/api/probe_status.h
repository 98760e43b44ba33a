#pragma once

#include <QList>
#include <QString>
#include <QVariantMap>
#include <deque>
#include <optional>

#include "devices/api/device.h"
#include "devices/parsers/probe_session.h"

namespace tt::devices {

/// What a probe-mandrel device does with its protocol session, the same for the serial plugin
/// and the built-in simulator: the session made from the settings (rateHz, silenceTimeoutMs,
/// replyTimeoutMs), the samples queued for the engine (past kMaxQueued the oldest is dropped and
/// counted), the table upload, what the mandrel reported, and the Devices page counters.
/// The device drives the session (poll/receive) and its own state; this holds the rest.
class ProbeSessionPorts : public core::DeflectionProbe, public TableUploadTarget {
public:
    static constexpr std::size_t kMaxQueued = 8192;

    std::optional<core::ProbeSample> takeSample() override;
    void uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    TableUploadStatus uploadStatus() const override;
    std::optional<MandrelTableInfo> tableInfo() const override;
    std::optional<MandrelInfo> mandrelInfo() const override;

protected:
    explicit ProbeSessionPorts(const QVariantMap& settings);

    /// Moves the samples the session decoded since the last call into the queue.
    void queueSessionSamples();
    /// The latest deflections in both planes ("0.0200 / -0.0050 mm"), or empty before the first.
    QString lastSampleText() const;
    /// Frames, losses, resends, the protocol and the table, for the Devices page.
    QList<DeviceStatistic> sessionStatistics() const;

    probe::ProbeSession m_session;

private:
    std::deque<core::ProbeSample> m_samples;
    std::uint64_t m_overflow = 0;
};

}  // namespace tt::devices
