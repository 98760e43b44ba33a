#include "devices/api/serial_settings.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSerialPort>
#include <QSerialPortInfo>

namespace tt::devices {

const QList<qint64>& standardBaudRates() {
    static const QList<qint64> rates{1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200};
    return rates;
}

SettingsSchema serialFields(qint64 defaultBaud, int defaultDataBits, const QString& defaultParity) {
    SettingsSchema fields;
    fields << SettingField::serialPort(
        QStringLiteral("port"), QCoreApplication::translate("DeviceSettings", "Serial port"), QString(),
        QCoreApplication::translate("DeviceSettings",
                                    "The port the cable is plugged into, e.g. /dev/ttyUSB0 or COM3."));
    SettingField baud =
        SettingField::integer(QStringLiteral("baud"), QCoreApplication::translate("DeviceSettings", "Baud rate"),
                              defaultBaud, 1200, 115200, QCoreApplication::translate("DeviceSettings", "bit/s"),
                              QCoreApplication::translate("DeviceSettings", "Must match the instrument's setting."));
    baud.allowedValues = standardBaudRates();
    fields << baud;
    fields << SettingField::choice(
        QStringLiteral("dataBits"), QCoreApplication::translate("DeviceSettings", "Data bits"),
        {{QStringLiteral("7"), QStringLiteral("7")}, {QStringLiteral("8"), QStringLiteral("8")}},
        QString::number(defaultDataBits));
    fields << SettingField::choice(QStringLiteral("parity"), QCoreApplication::translate("DeviceSettings", "Parity"),
                                   {{QStringLiteral("none"), QCoreApplication::translate("DeviceSettings", "None")},
                                    {QStringLiteral("even"), QCoreApplication::translate("DeviceSettings", "Even")},
                                    {QStringLiteral("odd"), QCoreApplication::translate("DeviceSettings", "Odd")}},
                                   defaultParity);
    fields << SettingField::choice(
        QStringLiteral("stopBits"), QCoreApplication::translate("DeviceSettings", "Stop bits"),
        {{QStringLiteral("1"), QStringLiteral("1")}, {QStringLiteral("2"), QStringLiteral("2")}}, QStringLiteral("1"));
    return fields;
}

QString serialSystemLocation(const QString& portName) {
    if (portName.startsWith(QLatin1Char('/'))) return portName;
#ifdef Q_OS_WIN
    return portName;
#else
    return QStringLiteral("/dev/") + portName;
#endif
}

bool serialPortExists(const QString& portName) {
    const QString name = portName.trimmed();
    if (name.isEmpty()) return false;
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        if (info.portName() == name || info.systemLocation() == name) return true;
#ifdef Q_OS_WIN
    return false;
#else
    return QFileInfo::exists(serialSystemLocation(name));
#endif
}

QStringList availableSerialPorts() {
    QStringList ports;
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        ports << info.systemLocation();
    ports.sort();
    return ports;
}

void applySerialLine(QSerialPort& port, const QVariantMap& settings) {
    port.setPortName(serialSystemLocation(settings.value(QStringLiteral("port")).toString().trimmed()));
    port.setBaudRate(settings.value(QStringLiteral("baud"), 9600).toInt());
    port.setDataBits(settings.value(QStringLiteral("dataBits")).toString() == QLatin1String("7") ? QSerialPort::Data7
                                                                                                 : QSerialPort::Data8);
    const QString parity = settings.value(QStringLiteral("parity")).toString();
    port.setParity(parity == QLatin1String("even")  ? QSerialPort::EvenParity
                   : parity == QLatin1String("odd") ? QSerialPort::OddParity
                                                    : QSerialPort::NoParity);
    port.setStopBits(settings.value(QStringLiteral("stopBits")).toString() == QLatin1String("2")
                         ? QSerialPort::TwoStop
                         : QSerialPort::OneStop);
    port.setFlowControl(QSerialPort::NoFlowControl);
}

}  // namespace tt::devices
