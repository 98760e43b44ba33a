#pragma once

// Modbus servers started by the tests: TCP on 127.0.0.1 (a free port) and RTU on one end of a
// pseudo-terminal null modem. Header-only.
#include <QHostAddress>
#include <QModbusRtuSerialServer>
#include <QModbusTcpServer>
#include <QSerialPort>
#include <QTcpServer>
#include <memory>
#include <stdexcept>
#include <vector>

namespace tt::devices::test {

/// A port nobody listens on right now (bind to 0, read it, release it).
inline quint16 freeTcpPort() {
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost, 0)) throw std::runtime_error("no free TCP port");
    const quint16 port = probe.serverPort();
    probe.close();
    return port;
}

/// 50 input and 300 holding registers, unit 1.
inline void giveRegisters(QModbusServer& server) {
    QModbusDataUnitMap map;
    map.insert(QModbusDataUnit::InputRegisters, {QModbusDataUnit::InputRegisters, 0, 50});
    map.insert(QModbusDataUnit::HoldingRegisters, {QModbusDataUnit::HoldingRegisters, 0, 300});
    server.setMap(map);
    server.setServerAddress(1);
}

/// Sets consecutive registers.
inline void setRegisters(QModbusServer& server, QModbusDataUnit::RegisterType table, quint16 start,
                         const std::vector<std::uint16_t>& words) {
    for (std::size_t i = 0; i < words.size(); ++i)
        server.setData(table, static_cast<quint16>(start + i), words[i]);
}

/// Reads consecutive registers.
inline std::vector<std::uint16_t> registers(const QModbusServer& server, QModbusDataUnit::RegisterType table,
                                            quint16 start, quint16 count) {
    std::vector<std::uint16_t> words;
    for (quint16 i = 0; i < count; ++i) {
        quint16 v = 0;
        server.data(table, static_cast<quint16>(start + i), &v);
        words.push_back(v);
    }
    return words;
}

/// A Modbus TCP server on 127.0.0.1:port.
inline std::unique_ptr<QModbusTcpServer> startTcpServer(quint16 port) {
    auto server = std::make_unique<QModbusTcpServer>();
    giveRegisters(*server);
    server->setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    server->setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    if (!server->connectDevice()) throw std::runtime_error("the Modbus TCP server did not start");
    return server;
}

/// A Modbus RTU server on the serial port `portName` (115200 8N1).
inline std::unique_ptr<QModbusRtuSerialServer> startRtuServer(const QString& portName) {
    auto server = std::make_unique<QModbusRtuSerialServer>();
    giveRegisters(*server);
    server->setConnectionParameter(QModbusDevice::SerialPortNameParameter, portName);
    server->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, QSerialPort::Baud115200);
    server->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    server->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    server->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    if (!server->connectDevice()) throw std::runtime_error("the Modbus RTU server did not start");
    return server;
}

}  // namespace tt::devices::test
