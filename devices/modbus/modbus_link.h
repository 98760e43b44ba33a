#pragma once

#include <QString>
#include <QTimer>
#include <QVariantMap>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "devices/parsers/modbus_registers.h"

class QModbusClient;
class QModbusReply;

namespace tt::devices {

/// Outcome of one Modbus request.
struct ModbusResult {
    bool ok = false;
    std::vector<std::uint16_t> words;           ///< registers read (reads only)
    bool timeout = false;                       ///< no reply within the timeout (after the retries)
    std::optional<std::uint8_t> exceptionCode;  ///< the server answered with a Modbus exception
    QString error;                              ///< in the user's terms, naming the exception
};

/// A Modbus client (Qt SerialBus: QModbusTcpClient or QModbusRtuSerialClient) that reconnects
/// by itself: after the connection is lost it retries with a growing back-off (0.2 s doubling
/// to 5 s) until close(). Requests report their outcome to a callback, with Modbus exceptions
/// named ("illegal data address"). Not a QObject, so plugins share no meta-objects.
/// Settings: see modbusConnectionFields().
class ModbusLink {
public:
    struct Callbacks {
        std::function<void()> onConnected;
        std::function<void(const QString&)> onLost;  ///< could not connect, or lost; the reason
    };
    using Done = std::function<void(const ModbusResult&)>;

    ModbusLink(QVariantMap settings, Callbacks callbacks);
    ~ModbusLink();
    ModbusLink(const ModbusLink&) = delete;
    ModbusLink& operator=(const ModbusLink&) = delete;

    void open();
    void close();
    bool isConnected() const;
    /// "127.0.0.1:502, unit 1", for messages.
    QString endpoint() const { return m_endpoint; }

    /// Reads a block; false (no callback) when not connected or the request cannot be sent.
    bool read(const modbus::ReadBlock& block, Done done);
    /// Writes holding registers from `start`; false when not connected.
    bool write(std::uint16_t start, const std::vector<std::uint16_t>& words, Done done);
    /// Requests sent whose reply has not arrived.
    int inFlight() const { return m_inFlight; }

private:
    void attempt();
    void lost(const QString& reason);
    void watch(QModbusReply* reply, const QString& what, Done done);

    QVariantMap m_settings;
    QString m_endpoint;
    int m_unitId;
    Callbacks m_callbacks;
    std::unique_ptr<QModbusClient> m_client;
    QTimer m_retry;
    int m_backoffMs = 200;
    bool m_wanted = false;
    bool m_connectedOnce = false;
    int m_inFlight = 0;
};

}  // namespace tt::devices
