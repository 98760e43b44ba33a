#pragma once

#include <QByteArray>
#include <QString>
#include <QTimer>
#include <QVariantMap>
#include <functional>
#include <memory>

class QSerialPort;

namespace tt::devices {

/// A serial connection that survives unplugging: opens the port with the line settings,
/// hands received bytes to a callback, reports a lost port (unplugged adapter, closed
/// pseudo-terminal) and reopens it with a growing back-off (0.25 s doubling to 4 s) until
/// close(). Not a QObject: plugins can use it without sharing meta-objects with the host.
class SerialLink {
public:
    struct Callbacks {
        std::function<void(const QByteArray&)> onBytes;  ///< bytes arrived
        std::function<void()> onOpened;                  ///< the port is open (first time or again)
        /// Could not open, or lost (`disconnected` true: it was open and went away); the reason.
        std::function<void(const QString& reason, bool disconnected)> onLost;
    };

    /// `settings`: the serial fields (see serial_settings.h). `what`: the device for messages ("gauge").
    SerialLink(QVariantMap settings, QString what, Callbacks callbacks);
    ~SerialLink();
    SerialLink(const SerialLink&) = delete;
    SerialLink& operator=(const SerialLink&) = delete;

    /// Opens now; on failure keeps trying with back-off.
    void open();
    /// Closes and stops trying.
    void close();
    bool isOpen() const;
    /// Writes bytes; false (and nothing sent) when the port is not open.
    bool write(const QByteArray& bytes);
    /// The port name as configured ("/dev/ttyUSB0").
    QString portName() const { return m_portName; }
    /// Open attempts that failed since the last success.
    int failedAttempts() const { return m_failedAttempts; }

private:
    void attempt();
    void lost(const QString& reason);
    void scheduleRetry();

    QVariantMap m_settings;
    QString m_what;
    QString m_portName;
    Callbacks m_callbacks;
    std::unique_ptr<QSerialPort> m_port;
    QTimer m_retry;
    int m_backoffMs = 250;
    int m_failedAttempts = 0;
    bool m_wanted = false;
    QString m_disconnected;  ///< why the port was lost, kept while reopening fails
};

}  // namespace tt::devices
