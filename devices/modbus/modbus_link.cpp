#include "devices/modbus/modbus_link.h"

#include <QCoreApplication>
#include <QModbusReply>

#include <QModbusRtuSerialClient>
#include <QModbusTcpClient>
#include <QSerialPort>
#include "devices/api/device_log.h"

#include "devices/api/device_log.h"
#include "devices/api/serial_settings.h"
#include "devices/modbus/modbus_settings.h"

namespace tt::devices {

namespace {

constexpr int kFirstBackoffMs = 200;
constexpr int kMaxBackoffMs = 5000;

QSerialPort::Parity parityOf(const QString& parity) {
    if (parity == QLatin1String("even")) return QSerialPort::EvenParity;
    if (parity == QLatin1String("odd")) return QSerialPort::OddParity;
    return QSerialPort::NoParity;
}

}  // namespace

ModbusLink::ModbusLink(QVariantMap settings, Callbacks callbacks)
    : m_settings(std::move(settings)),
      m_endpoint(modbusEndpoint(m_settings)),
      m_unitId(m_settings.value(QStringLiteral("unitId"), 1).toInt()),
      m_callbacks(std::move(callbacks)) {
    if (m_settings.value(QStringLiteral("transport")).toString() == QLatin1String("rtu")) {
        auto client = std::make_unique<QModbusRtuSerialClient>();
        client->setConnectionParameter(
            QModbusDevice::SerialPortNameParameter,
            serialSystemLocation(m_settings.value(QStringLiteral("port")).toString().trimmed()));
        client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter,
                                       m_settings.value(QStringLiteral("baud"), 19200).toInt());
        client->setConnectionParameter(QModbusDevice::SerialParityParameter,
                                       parityOf(m_settings.value(QStringLiteral("parity")).toString()));
        client->setConnectionParameter(QModbusDevice::SerialDataBitsParameter,
                                       m_settings.value(QStringLiteral("dataBits")).toString() == QLatin1String("7")
                                           ? QSerialPort::Data7
                                           : QSerialPort::Data8);
        client->setConnectionParameter(QModbusDevice::SerialStopBitsParameter,
                                       m_settings.value(QStringLiteral("stopBits")).toString() == QLatin1String("2")
                                           ? QSerialPort::TwoStop
                                           : QSerialPort::OneStop);
        m_client = std::move(client);
    } else {
        auto client = std::make_unique<QModbusTcpClient>();
        client->setConnectionParameter(QModbusDevice::NetworkAddressParameter,
                                       m_settings.value(QStringLiteral("host")).toString().trimmed());
        client->setConnectionParameter(QModbusDevice::NetworkPortParameter,
                                       m_settings.value(QStringLiteral("tcpPort"), 502).toInt());
        m_client = std::move(client);
    }
    m_client->setTimeout(m_settings.value(QStringLiteral("timeoutMs"), 200).toInt());
    m_client->setNumberOfRetries(m_settings.value(QStringLiteral("retries"), 1).toInt());
    m_retry.setSingleShot(true);
    QObject::connect(&m_retry, &QTimer::timeout, [this] { attempt(); });
    QObject::connect(m_client.get(), &QModbusDevice::stateChanged, [this](QModbusDevice::State state) {
        if (state == QModbusDevice::ConnectedState) {
            m_backoffMs = kFirstBackoffMs;
            m_connectedOnce = true;
            if (m_callbacks.onConnected) m_callbacks.onConnected();
        } else if (state == QModbusDevice::UnconnectedState && m_wanted) {
            const QString why = m_client->error() != QModbusDevice::NoError
                                    ? m_client->errorString()
                                    : QCoreApplication::translate("Modbus", "connection closed");
            lost((m_connectedOnce ? QCoreApplication::translate("Modbus", "lost the connection to %1 (%2)")
                                  : QCoreApplication::translate("Modbus", "cannot connect to %1 (%2)"))
                     .arg(m_endpoint, why));
        }
    });
}

ModbusLink::~ModbusLink() {
    m_wanted = false;
    m_retry.stop();
    m_client->disconnect();
    m_client->disconnectDevice();
}

void ModbusLink::open() {
    m_wanted = true;
    m_backoffMs = kFirstBackoffMs;
    if (m_client->state() != QModbusDevice::UnconnectedState) return;
    attempt();
}

void ModbusLink::close() {
    m_wanted = false;
    m_retry.stop();
    m_client->disconnectDevice();
}

bool ModbusLink::isConnected() const {
    return m_client->state() == QModbusDevice::ConnectedState;
}

void ModbusLink::attempt() {
    if (!m_wanted || m_client->state() != QModbusDevice::UnconnectedState) return;
    if (!m_client->connectDevice() && m_client->state() == QModbusDevice::UnconnectedState)
        lost(QCoreApplication::translate("Modbus", "cannot connect to %1 (%2)")
                 .arg(m_endpoint, m_client->errorString()));
}

void ModbusLink::lost(const QString& reason) {
    if (m_callbacks.onLost) m_callbacks.onLost(reason);
    if (!m_wanted || m_retry.isActive()) return;
    m_retry.start(m_backoffMs);
    m_backoffMs = std::min(m_backoffMs * 2, kMaxBackoffMs);
}

bool ModbusLink::read(const modbus::ReadBlock& block, Done done) {
    if (!isConnected()) return false;
    const auto table = block.table == modbus::RegisterTable::Input ? QModbusDataUnit::InputRegisters
                                                                   : QModbusDataUnit::HoldingRegisters;
    QModbusReply* reply = m_client->sendReadRequest(QModbusDataUnit(table, block.start, block.count), m_unitId);
    if (!reply) return false;
    watch(
        reply,
        QCoreApplication::translate("Modbus", "reading %n register(s) from %1", nullptr, block.count).arg(block.start),
        std::move(done));
    return true;
}

bool ModbusLink::write(std::uint16_t start, const std::vector<std::uint16_t>& words, Done done) {
    if (!isConnected() || words.empty()) return false;
    QModbusDataUnit unit(QModbusDataUnit::HoldingRegisters, start, static_cast<quint16>(words.size()));
    for (std::size_t i = 0; i < words.size(); ++i)
        unit.setValue(static_cast<qsizetype>(i), words[i]);
    QModbusReply* reply = m_client->sendWriteRequest(unit, m_unitId);
    if (!reply) return false;
    const int count = static_cast<int>(words.size());
    watch(reply, QCoreApplication::translate("Modbus", "writing %n register(s) at %1", nullptr, count).arg(start),
          std::move(done));
    return true;
}

void ModbusLink::watch(QModbusReply* reply, const QString& what, Done done) {
    ++m_inFlight;
    qCDebug(lcDeviceTraffic).noquote() << m_endpoint << "->" << what;
    auto finish = [this, reply, what, done = std::move(done)] {
        --m_inFlight;
        ModbusResult r;
        switch (reply->error()) {
            case QModbusDevice::NoError: {
                r.ok = true;
                const QList<quint16> values = reply->result().values();
                r.words.assign(values.begin(), values.end());
                break;
            }
            case QModbusDevice::ProtocolError:
                if (reply->rawResult().isException()) {
                    r.exceptionCode = static_cast<std::uint8_t>(reply->rawResult().exceptionCode());
                    r.error = QCoreApplication::translate("Modbus", "Modbus exception %1 (%2) %3 of %4")
                                  .arg(*r.exceptionCode)
                                  .arg(QString::fromStdString(modbus::modbusExceptionName(*r.exceptionCode)), what,
                                       m_endpoint);
                } else {
                    r.error = QCoreApplication::translate("Modbus", "invalid reply %1 of %2: %3")
                                  .arg(what, m_endpoint, reply->errorString());
                }
                break;
            case QModbusDevice::TimeoutError:
                r.timeout = true;
                r.error = QCoreApplication::translate("Modbus", "no answer from %1 within %2 ms (%3)")
                              .arg(m_endpoint)
                              .arg(m_client->timeout())
                              .arg(what);
                break;
            default:
                r.error = QCoreApplication::translate("Modbus", "%1 of %2 failed: %3")
                              .arg(what, m_endpoint, reply->errorString());
                break;
        }
        if (r.ok)
            qCDebug(lcDeviceTraffic).noquote() << m_endpoint << "<-" << r.words;
        else
            qCWarning(lcDevices).noquote() << r.error;
        reply->deleteLater();
        done(r);
    };
    if (reply->isFinished()) {
        finish();
        return;
    }
    QObject::connect(reply, &QModbusReply::finished, reply, finish);
}

}  // namespace tt::devices
