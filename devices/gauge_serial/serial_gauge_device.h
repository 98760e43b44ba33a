#pragma once

#include <QByteArray>
#include <QTimer>
#include <QVariantMap>
#include <deque>
#include <memory>
#include <optional>

#include "devices/api/device_base.h"
#include "devices/api/serial_link.h"
#include "devices/parsers/gauge_decoder.h"

namespace tt::devices {

/// A gauge micrometer on a serial port (Qt SerialPort): the ASCII output of data cables
/// (`01A+00026.812` CR, typically 9600 8N1) or the 13-nibble Digimatic frame of data loggers,
/// pushed by the instrument's DATA button or polled with a configurable request string.
/// Readings are converted to mm and checked against the job's unit (an inch reading on a mm
/// job is refused with a message). The port is reopened after unplugging; in polled mode a
/// request without an answer within the timeout puts the device in error.
/// Settings: the serial fields, format, instrumentUnit, jobUnit, mode (push/polled),
/// request, replyTimeoutMs.
class SerialGaugeDevice final : public DeviceBase, public core::DiameterGauge {
public:
    SerialGaugeDevice(const QVariantMap& settings, const DeviceContext& context);
    ~SerialGaugeDevice() override;

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    void requestReading() override;
    std::optional<core::GaugeReading> takeReading() override;
    core::DiameterGauge* diameterGauge() override { return this; }
    QList<DeviceStatistic> statistics() const override;

private:
    void opened();
    void lost(const QString& reason, bool disconnected);
    void bytesArrived(const QByteArray& bytes);
    void timedOut();
    QString readyMessage() const;

    bool m_polled;
    QByteArray m_request;
    int m_replyTimeoutMs;
    GaugeDecoder m_decoder;
    std::unique_ptr<SerialLink> m_link;
    QTimer m_replyTimer;
    bool m_testPending = false;
    std::deque<core::GaugeReading> m_readings;
    std::uint64_t m_timeouts = 0;
};

}  // namespace tt::devices
