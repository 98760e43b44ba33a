#pragma once

#include <QByteArray>
#include <QTimer>
#include <QVariantMap>
#include <deque>
#include <memory>

#include "devices/api/device_base.h"
#include "devices/api/serial_link.h"
#include "devices/parsers/probe_session.h"

namespace tt::devices {

/// The probe mandrel (paper 001, way 2) on RS-232/RS-485 (Qt SerialPort), speaking the frame
/// protocol of docs/protocols/probe-mandrel.md through ProbeSession: handshake, streaming,
/// lost/duplicated/corrupt frames counted and never used, silence detection, table upload with
/// verification. The port is reopened after unplugging and the handshake repeated.
/// Settings: the serial fields, rateHz, silenceTimeoutMs, replyTimeoutMs.
class SerialProbeDevice final : public DeviceBase, public core::DeflectionProbe, public TableUploadTarget {
public:
    SerialProbeDevice(const QVariantMap& settings, const DeviceContext& context);
    ~SerialProbeDevice() override;

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    std::optional<core::ProbeSample> takeSample() override;
    core::DeflectionProbe* deflectionProbe() override { return this; }
    TableUploadTarget* tableUploadTarget() override { return this; }
    QList<DeviceStatistic> statistics() const override;

    void uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override;
    TableUploadStatus uploadStatus() const override;
    std::optional<MandrelTableInfo> tableInfo() const override;
    std::optional<MandrelInfo> mandrelInfo() const override;

private:
    void opened();
    void lost(const QString& reason, bool disconnected);
    void bytesArrived(const QByteArray& bytes);
    void tick();
    void updateState();

    probe::ProbeSession m_session;
    std::unique_ptr<SerialLink> m_link;
    QTimer m_timer;
    std::deque<core::ProbeSample> m_samples;
    std::uint64_t m_overflow = 0;
    QString m_linkProblem;
};

}  // namespace tt::devices
