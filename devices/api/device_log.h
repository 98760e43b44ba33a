#pragma once

#include <QLoggingCategory>

/// Device connections and states ("trueturn.devices"), and the bytes on the wire at debug level
/// ("trueturn.devices.traffic", for commissioning: QT_LOGGING_RULES="trueturn.devices.traffic.debug=true").
Q_DECLARE_LOGGING_CATEGORY(lcDevices)
Q_DECLARE_LOGGING_CATEGORY(lcDeviceTraffic)
