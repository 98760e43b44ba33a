#include "devices/api/serial_link.h"

#include "devices/api/device_log.h"

#include <QCoreApplication>
#include <QSerialPort>

#include "devices/api/serial_settings.h"

namespace tt::devices {

namespace {
constexpr int kFirstBackoffMs = 250;
constexpr int kMaxBackoffMs = 4000;
}  // namespace

SerialLink::SerialLink(QVariantMap settings, QString what, Callbacks callbacks)
    : m_settings(std::move(settings)),
      m_what(std::move(what)),
      m_portName(m_settings.value(QStringLiteral("port")).toString().trimmed()),
      m_callbacks(std::move(callbacks)),
      m_port(std::make_unique<QSerialPort>()) {
    m_retry.setSingleShot(true);
    QObject::connect(&m_retry, &QTimer::timeout, [this] { attempt(); });
    QObject::connect(m_port.get(), &QSerialPort::readyRead, [this] {
        const QByteArray bytes = m_port->readAll();
        qCDebug(lcDeviceTraffic).noquote() << m_portName << "<-" << bytes.toHex(' ');
        if (!bytes.isEmpty() && m_callbacks.onBytes) m_callbacks.onBytes(bytes);
    });
    QObject::connect(m_port.get(), &QSerialPort::errorOccurred, [this](QSerialPort::SerialPortError error) {
        if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError || !m_port->isOpen()) return;
        // Qt's own text for a vanished port is the stale errno ("File exists"): say what happened.
        const QString what =
            error == QSerialPort::ResourceError
                ? QCoreApplication::translate("SerialLink", "the port went away: cable or adapter unplugged")
            : error == QSerialPort::ReadError  ? QCoreApplication::translate("SerialLink", "reading failed")
            : error == QSerialPort::WriteError ? QCoreApplication::translate("SerialLink", "writing failed")
                                               : m_port->errorString();
        lost(QCoreApplication::translate("SerialLink", "the %1 on %2 was disconnected (%3)")
                 .arg(m_what, m_portName, what));
    });
}

SerialLink::~SerialLink() {
    m_wanted = false;
    m_retry.stop();
    m_port->disconnect();
    if (m_port->isOpen()) m_port->close();
}

void SerialLink::open() {
    m_wanted = true;
    m_backoffMs = kFirstBackoffMs;
    m_failedAttempts = 0;
    if (m_port->isOpen()) m_port->close();
    attempt();
}

void SerialLink::close() {
    m_wanted = false;
    m_disconnected.clear();
    m_retry.stop();
    if (m_port->isOpen()) m_port->close();
}

bool SerialLink::isOpen() const {
    return m_port->isOpen();
}

bool SerialLink::write(const QByteArray& bytes) {
    if (!m_port->isOpen()) return false;
    qCDebug(lcDeviceTraffic).noquote() << m_portName << "->" << bytes.toHex(' ');
    return m_port->write(bytes) == bytes.size();
}

void SerialLink::attempt() {
    if (!m_wanted) return;
    applySerialLine(*m_port, m_settings);
    if (m_port->open(QIODevice::ReadWrite)) {
        m_port->clear();
        m_disconnected.clear();
        m_backoffMs = kFirstBackoffMs;
        m_failedAttempts = 0;
        qCInfo(lcDevices).noquote() << "opened" << m_portName << "for the" << m_what;
        if (m_callbacks.onOpened) m_callbacks.onOpened();
        return;
    }
    ++m_failedAttempts;
    const QString reason = m_port->errorString();
    if (m_callbacks.onLost)
        m_callbacks.onLost(
            m_disconnected.isEmpty()
                ? QCoreApplication::translate("SerialLink", "cannot open %1 for the %2: %3")
                      .arg(m_portName, m_what, reason)
                : QCoreApplication::translate("SerialLink", "%1; reopening (%2)").arg(m_disconnected, reason),
            false);
    scheduleRetry();
}

void SerialLink::lost(const QString& reason) {
    if (m_port->isOpen()) m_port->close();
    m_disconnected = reason;
    qCWarning(lcDevices).noquote() << reason;
    if (m_callbacks.onLost) m_callbacks.onLost(reason, true);
    scheduleRetry();
}

void SerialLink::scheduleRetry() {
    if (!m_wanted) return;
    m_retry.start(m_backoffMs);
    m_backoffMs = std::min(m_backoffMs * 2, kMaxBackoffMs);
}

}  // namespace tt::devices
