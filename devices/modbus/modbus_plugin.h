#pragma once

#include <QObject>

#include "devices/modbus/modbus_factory.h"

namespace tt::devices {

/// The Qt plugin that exports ModbusFactory (libtrueturn_modbus.so).
class ModbusPlugin final : public QObject, public ModbusFactory {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)
};

}  // namespace tt::devices
