#pragma once

#include <QList>
#include <QString>
#include <QStringList>
#include <QVariantMap>

#include "devices/api/settings_schema.h"

class QSerialPort;

namespace tt::devices {

/// The standard baud rates offered and accepted for serial devices.
const QList<qint64>& standardBaudRates();

/// The serial-line fields shared by the serial plugins: port, baud rate, data bits, parity,
/// stop bits (keys "port", "baud", "dataBits", "parity", "stopBits").
SettingsSchema serialFields(qint64 defaultBaud, int defaultDataBits = 8, const QString& defaultParity = "none");

/// Where a port name lives: "/dev/ttyUSB0" for "ttyUSB0"; absolute paths (also symbolic links
/// to pseudo-terminals) unchanged; "COM3" unchanged.
QString serialSystemLocation(const QString& portName);
/// Whether the port exists on this computer now.
bool serialPortExists(const QString& portName);
/// The serial ports present now (system locations, e.g. /dev/ttyUSB0), for a port chooser.
QStringList availableSerialPorts();

/// Applies the line settings of `settings` (see serialFields) to `port` before it is opened.
void applySerialLine(QSerialPort& port, const QVariantMap& settings);

}  // namespace tt::devices
