#pragma once

#include <QString>
#include <QVariantMap>

#include "devices/api/settings_schema.h"
#include "devices/parsers/drive_units.h"
#include "devices/parsers/modbus_registers.h"

namespace tt::devices {

/// The connection fields of a Modbus device: transport ("tcp"/"rtu"), host and TCP port, the
/// serial fields for RTU, the unit id (server address), the reply timeout and retries.
SettingsSchema modbusConnectionFields();

/// The fields of one value of a register map, keys prefixed with `prefix` ("current"):
/// <prefix>Table, <prefix>Address, <prefix>Type, <prefix>WordOrder, <prefix>Scale and, when
/// `units` is non-empty, <prefix>Unit.
SettingsSchema registerFields(const QString& prefix, const QString& label, quint16 defaultAddress,
                              modbus::RegisterType defaultType, double defaultScale, const QStringList& units = {},
                              const QString& defaultUnit = {});

/// The register spec stored under `prefix` (see registerFields).
modbus::RegisterSpec registerSpec(const QVariantMap& settings, const QString& prefix);

/// "127.0.0.1:502, unit 1" or "/dev/ttyUSB0, unit 1", for messages.
QString modbusEndpoint(const QVariantMap& settings);

}  // namespace tt::devices
