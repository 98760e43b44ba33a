#include "devices/gauge_serial/serial_gauge_device.h"

#include <QCoreApplication>

#include "devices/api/gauge_settings.h"
#include "devices/parsers/request_string.h"

namespace tt::devices {

namespace {
constexpr std::size_t kMaxQueued = 256;
}

SerialGaugeDevice::SerialGaugeDevice(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::Gauge, context),
      m_polled(settings.value(QStringLiteral("mode")).toString() == QLatin1String("polled")),
      m_request(QByteArray::fromStdString(
          unescapeRequest(settings.value(QStringLiteral("request")).toString().toStdString()).value_or("\r"))),
      m_replyTimeoutMs(settings.value(QStringLiteral("replyTimeoutMs"), 1000).toInt()),
      m_decoder(gaugeFormat(settings), instrumentUnit(settings), jobUnit(settings)) {
    m_link = std::make_unique<SerialLink>(
        settings, QCoreApplication::translate("SerialGauge", "gauge"),
        SerialLink::Callbacks{[this](const QByteArray& bytes) { bytesArrived(bytes); }, [this] { opened(); },
                              [this](const QString& reason, bool disconnected) { lost(reason, disconnected); }});
    m_replyTimer.setSingleShot(true);
    QObject::connect(&m_replyTimer, &QTimer::timeout, [this] { timedOut(); });
}

SerialGaugeDevice::~SerialGaugeDevice() {
    m_replyTimer.stop();
}

QString SerialGaugeDevice::readyMessage() const {
    return m_polled ? QCoreApplication::translate("SerialGauge", "%1 open; readings on request").arg(m_link->portName())
                    : QCoreApplication::translate("SerialGauge", "%1 open; press DATA on the micrometer")
                          .arg(m_link->portName());
}

void SerialGaugeDevice::open() {
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("SerialGauge", "opening %1").arg(m_link->portName()));
    m_link->open();
}

void SerialGaugeDevice::close() {
    m_replyTimer.stop();
    m_testPending = false;
    m_link->close();
    setState(core::DeviceState::Disconnected);
}

void SerialGaugeDevice::testConnection() {
    if (!m_link->isOpen()) {
        m_testPending = true;
        open();
        return;
    }
    requestReading();
}

void SerialGaugeDevice::opened() {
    m_decoder.reset();
    setState(core::DeviceState::Ready, readyMessage());
    if (m_testPending) {
        m_testPending = false;
        requestReading();
    }
}

void SerialGaugeDevice::lost(const QString& reason, bool disconnected) {
    if (disconnected) reportError(reason);
    m_replyTimer.stop();
    m_decoder.reset();
    setState(core::DeviceState::Error, reason);
}

void SerialGaugeDevice::requestReading() {
    if (!m_polled || !m_link->isOpen()) return;
    if (m_link->write(m_request) && !m_replyTimer.isActive()) m_replyTimer.start(m_replyTimeoutMs);
}

void SerialGaugeDevice::timedOut() {
    ++m_timeouts;
    setState(core::DeviceState::Error,
             QCoreApplication::translate("SerialGauge", "no answer from the gauge on %1 for %2 s")
                 .arg(m_link->portName())
                 .arg(m_replyTimeoutMs / 1000.0, 0, 'f', 1));
}

void SerialGaugeDevice::bytesArrived(const QByteArray& bytes) {
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.constData());
    for (const GaugeDecoded& d : m_decoder.feed({data, static_cast<std::size_t>(bytes.size())})) {
        m_replyTimer.stop();  // the gauge answered, even if the frame is refused
        if (state() == core::DeviceState::Error) setState(core::DeviceState::Ready, readyMessage());
        if (!d.diameterMm) {
            reportError(QString::fromStdString(d.error));
            continue;
        }
        if (m_readings.size() == kMaxQueued) m_readings.pop_front();
        m_readings.push_back({*d.diameterMm, now()});
        setLiveValue(QStringLiteral("%1 %2")
                         .arg(d.value, 0, 'f', d.decimals)
                         .arg(d.unit == LengthUnit::Inch ? QCoreApplication::translate("SerialGauge", "in")
                                                         : QCoreApplication::translate("SerialGauge", "mm")));
    }
}

std::optional<core::GaugeReading> SerialGaugeDevice::takeReading() {
    if (m_readings.empty()) return std::nullopt;
    const core::GaugeReading r = m_readings.front();
    m_readings.pop_front();
    return r;
}

QList<DeviceStatistic> SerialGaugeDevice::statistics() const {
    return {
        {QCoreApplication::translate("SerialGauge", "Readings accepted"), QString::number(m_decoder.accepted())},
        {QCoreApplication::translate("SerialGauge", "Malformed frames"), QString::number(m_decoder.malformed())},
        {QCoreApplication::translate("SerialGauge", "Readings refused"), QString::number(m_decoder.refused())},
        {QCoreApplication::translate("SerialGauge", "Bytes discarded"), QString::number(m_decoder.discardedBytes())},
        {QCoreApplication::translate("SerialGauge", "Requests unanswered"), QString::number(m_timeouts)}};
}

}  // namespace tt::devices
