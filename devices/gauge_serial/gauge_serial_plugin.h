#pragma once

#include <QObject>

#include "devices/gauge_serial/gauge_serial_factory.h"

namespace tt::devices {

/// The Qt plugin that exports GaugeSerialFactory (libtrueturn_gauge_serial.so).
class GaugeSerialPlugin final : public QObject, public GaugeSerialFactory {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)
};

}  // namespace tt::devices
