#include "devices/probe_mandrel/serial_probe_device.h"

#include <QCoreApplication>

namespace tt::devices {

namespace {
constexpr int kTickMs = 5;
}  // namespace

SerialProbeDevice::SerialProbeDevice(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::Probe, context), ProbeSessionPorts(settings) {
    m_link = std::make_unique<SerialLink>(
        settings, QCoreApplication::translate("ProbeMandrel", "probe mandrel"),
        SerialLink::Callbacks{[this](const QByteArray& bytes) { bytesArrived(bytes); }, [this] { opened(); },
                              [this](const QString& reason, bool disconnected) { lost(reason, disconnected); }});
    m_timer.setInterval(kTickMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    QObject::connect(&m_timer, &QTimer::timeout, [this] { tick(); });
}

SerialProbeDevice::~SerialProbeDevice() {
    m_timer.stop();
}

void SerialProbeDevice::open() {
    setState(core::DeviceState::Connecting,
             QCoreApplication::translate("ProbeMandrel", "opening %1").arg(m_link->portName()));
    m_link->open();
}

void SerialProbeDevice::close() {
    if (m_link->isOpen()) {
        m_session.stop(now());
        const std::vector<std::uint8_t> bytes = m_session.poll(now());
        m_link->write(QByteArray(reinterpret_cast<const char*>(bytes.data()), static_cast<qsizetype>(bytes.size())));
    }
    m_timer.stop();
    m_link->close();
    setState(core::DeviceState::Disconnected);
}

void SerialProbeDevice::testConnection() {
    if (!m_link->isOpen()) {
        open();
        return;
    }
    m_session.requestTableInfo();
}

void SerialProbeDevice::opened() {
    m_linkProblem.clear();
    m_session.start(now());
    m_timer.start();
    updateState();
}

void SerialProbeDevice::lost(const QString& reason, bool disconnected) {
    if (disconnected) reportError(reason);
    m_timer.stop();
    m_linkProblem = reason;
    setState(core::DeviceState::Error, reason);
}

void SerialProbeDevice::bytesArrived(const QByteArray& bytes) {
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.constData());
    m_session.receive({data, static_cast<std::size_t>(bytes.size())}, now());
    // A reply may free the line for the next command (the next chunk of an upload): send it now
    // rather than at the next tick, so an upload runs at the speed of the line.
    const std::vector<std::uint8_t> out = m_session.poll(now());
    if (!out.empty())
        m_link->write(QByteArray(reinterpret_cast<const char*>(out.data()), static_cast<qsizetype>(out.size())));
}

void SerialProbeDevice::tick() {
    const std::vector<std::uint8_t> out = m_session.poll(now());
    if (!out.empty())
        m_link->write(QByteArray(reinterpret_cast<const char*>(out.data()), static_cast<qsizetype>(out.size())));
    queueSessionSamples();
    if (const QString live = lastSampleText(); !live.isEmpty()) setLiveValue(live);
    if (!m_session.lastError().empty() && QString::fromStdString(m_session.lastError()) != lastError())
        reportError(QString::fromStdString(m_session.lastError()));
    updateState();
}

void SerialProbeDevice::updateState() {
    if (!m_linkProblem.isEmpty()) return;
    switch (m_session.link()) {
        case probe::ProbeSession::Link::Streaming:
            setState(core::DeviceState::Ready,
                     QCoreApplication::translate("ProbeMandrel", "streaming from %1").arg(m_link->portName()));
            break;
        case probe::ProbeSession::Link::Handshake:
            setState(core::DeviceState::Connecting,
                     QCoreApplication::translate("ProbeMandrel", "starting the probe mandrel on %1")
                         .arg(m_link->portName()));
            break;
        case probe::ProbeSession::Link::Silent:
        case probe::ProbeSession::Link::Failed:
            setState(core::DeviceState::Error,
                     QCoreApplication::translate("ProbeMandrel", "%1 on %2")
                         .arg(QString::fromStdString(m_session.problem()), m_link->portName()));
            break;
        case probe::ProbeSession::Link::Idle:
            break;
    }
}

}  // namespace tt::devices
