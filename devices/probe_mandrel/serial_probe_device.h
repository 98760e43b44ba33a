#pragma once

#include <QByteArray>
#include <QTimer>
#include <QVariantMap>
#include <memory>

#include "devices/api/device_base.h"
#include "devices/api/probe_status.h"
#include "devices/api/serial_link.h"

namespace tt::devices {

/// The probe mandrel (paper 001, way 2) on RS-232/RS-485 (Qt SerialPort), speaking the frame
/// protocol of docs/protocols/probe-mandrel.md through ProbeSession: handshake, streaming,
/// lost/duplicated/corrupt frames counted and never used, silence detection, table upload with
/// verification. The port is reopened after unplugging and the handshake repeated.
/// Settings: the serial fields, rateHz, silenceTimeoutMs, replyTimeoutMs.
class SerialProbeDevice final : public DeviceBase, public ProbeSessionPorts {
public:
    SerialProbeDevice(const QVariantMap& settings, const DeviceContext& context);
    ~SerialProbeDevice() override;

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    core::DeflectionProbe* deflectionProbe() override { return this; }
    TableUploadTarget* tableUploadTarget() override { return this; }
    QList<DeviceStatistic> statistics() const override { return sessionStatistics(); }

private:
    void opened();
    void lost(const QString& reason, bool disconnected);
    void bytesArrived(const QByteArray& bytes);
    void tick();
    void updateState();

    std::unique_ptr<SerialLink> m_link;
    QTimer m_timer;
    QString m_linkProblem;
};

}  // namespace tt::devices
