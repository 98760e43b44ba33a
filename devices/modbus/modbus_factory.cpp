#include "devices/modbus/modbus_factory.h"

#include <QCoreApplication>

#include "devices/modbus/modbus_drive_device.h"
#include "devices/modbus/modbus_output_device.h"
#include "devices/modbus/modbus_settings.h"

namespace tt::devices {

using namespace modbus;

namespace {

QStringList unitNames(DriveQuantity quantity) {
    QStringList names;
    for (const std::string_view u : driveUnits(quantity))
        names << QString::fromLatin1(u.data(), static_cast<qsizetype>(u.size()));
    return names;
}

/// The label of a drive register's quantity ("current" -> "Current"), as the form shows it.
QString quantityLabel(const QString& key) {
    if (key == QLatin1String("current")) return QCoreApplication::translate("Modbus", "Current");
    if (key == QLatin1String("velocity")) return QCoreApplication::translate("Modbus", "Velocity");
    if (key == QLatin1String("position")) return QCoreApplication::translate("Modbus", "Position");
    return key;
}

SettingsSchema driveSchema() {
    SettingsSchema s = modbusConnectionFields();
    s << SettingField::integer(QStringLiteral("pollMs"), QCoreApplication::translate("Modbus", "Polling period"), 20,
                               10, 100, QCoreApplication::translate("Modbus", "ms"),
                               QCoreApplication::translate("Modbus", "The PLC cycle of paper 001: 10 to 100 ms."));
    s << registerFields(QStringLiteral("current"), quantityLabel(QStringLiteral("current")), 0, RegisterType::Int16,
                        0.01, unitNames(DriveQuantity::Current));
    s << registerFields(QStringLiteral("velocity"), quantityLabel(QStringLiteral("velocity")), 1, RegisterType::Int32,
                        0.001, unitNames(DriveQuantity::Velocity));
    s << registerFields(QStringLiteral("position"), quantityLabel(QStringLiteral("position")), 3, RegisterType::Int32,
                        0.0001, unitNames(DriveQuantity::Position));
    return s;
}

SettingsSchema outputSchema() {
    SettingsSchema s = modbusConnectionFields();
    s << SettingField::choice(
        QStringLiteral("target"), QCoreApplication::translate("Modbus", "What is written"),
        {{QStringLiteral("points"), QCoreApplication::translate("Modbus", "Per-point corrections of the next part")},
         {QStringLiteral("offset"), QCoreApplication::translate("Modbus", "Dynamic X offset, every PLC cycle")}},
        QStringLiteral("points"));
    s << SettingField::integer(QStringLiteral("pointsAddress"),
                               QCoreApplication::translate("Modbus", "First correction register"), 100, 0, 65535)
             .visibleWhen(QStringLiteral("target"), {QStringLiteral("points")});
    s << SettingField::integer(QStringLiteral("maxPoints"), QCoreApplication::translate("Modbus", "Control points"), 5,
                               1, 32, {}, QCoreApplication::translate("Modbus", "Paper 000 controls five points."))
             .visibleWhen(QStringLiteral("target"), {QStringLiteral("points")});
    s << SettingField::boolean(QStringLiteral("writePartNumber"),
                               QCoreApplication::translate("Modbus", "Write the part number last"), false,
                               QCoreApplication::translate(
                                   "Modbus", "A handshake: the PLC applies the corrections when the number changes."))
             .visibleWhen(QStringLiteral("target"), {QStringLiteral("points")});
    s << SettingField::integer(QStringLiteral("partAddress"),
                               QCoreApplication::translate("Modbus", "Part number register (int32)"), 110, 0, 65534)
             .visibleWhen(QStringLiteral("target"), {QStringLiteral("points")});
    s << SettingField::integer(QStringLiteral("offsetAddress"),
                               QCoreApplication::translate("Modbus", "X offset register"), 120, 0, 65535)
             .visibleWhen(QStringLiteral("target"), {QStringLiteral("offset")});
    SettingsSchema value = registerFields(QStringLiteral("value"), QCoreApplication::translate("Modbus", "Correction"),
                                          0, RegisterType::Int32, 0.0001);
    for (const SettingField& f : value)
        if (f.key != QLatin1String("valueTable") && f.key != QLatin1String("valueAddress")) s << f;
    s.last().unit = QCoreApplication::translate("Modbus", "mm per count");
    s << SettingField::number(QStringLiteral("maxCorrectionMm"),
                              QCoreApplication::translate("Modbus", "Correction limit"), 0.5, 0.001, 5.0,
                              QCoreApplication::translate("Modbus", "mm"), 3,
                              QCoreApplication::translate("Modbus", "Larger corrections are refused, never sent."));
    return s;
}

}  // namespace

SettingsSchema ModbusFactory::settingsSchema(DeviceKind kind) const {
    if (kind == DeviceKind::DriveCurrent) return driveSchema();
    if (kind == DeviceKind::CorrectionOutput) return outputSchema();
    return {};
}

QList<SettingIssue> ModbusFactory::validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const {
    QList<SettingIssue> issues = DevicePlugin::validate(kind, settings, depth);
    const QVariantMap v = withDefaults(settingsSchema(kind), settings);
    if (v.value(QStringLiteral("transport")).toString() == QLatin1String("tcp") &&
        v.value(QStringLiteral("host")).toString().trimmed().isEmpty())
        issues.append(
            {QStringLiteral("host"),
             QCoreApplication::translate("Modbus", "Host: enter the IP address or name of the drive or PLC")});
    if (kind == DeviceKind::DriveCurrent) {
        const std::vector<RegisterSpec> specs{registerSpec(v, QStringLiteral("current")),
                                              registerSpec(v, QStringLiteral("velocity")),
                                              registerSpec(v, QStringLiteral("position"))};
        try {
            (void)planReads(specs);
        } catch (const std::invalid_argument& e) {
            issues.append({QString::fromStdString(specs.front().name), QString::fromStdString(e.what())});
        }
        for (const RegisterSpec& spec : specs)
            if (spec.scale == 0.0)
                issues.append({QString::fromStdString(spec.name) + QStringLiteral("Scale"),
                               QCoreApplication::translate("Modbus", "%1: the scale must not be zero")
                                   .arg(quantityLabel(QString::fromStdString(spec.name)))});
    } else if (kind == DeviceKind::CorrectionOutput) {
        const RegisterType type = registerSpec(v, QStringLiteral("value")).type;
        const long end = v.value(QStringLiteral("pointsAddress")).toLongLong() +
                         static_cast<long>(registerCount(type)) * v.value(QStringLiteral("maxPoints")).toLongLong();
        if (end > 65536)
            issues.append({QStringLiteral("pointsAddress"),
                           QCoreApplication::translate(
                               "Modbus", "First correction register: the corrections run past address 65535")});
        if (registerSpec(v, QStringLiteral("value")).scale == 0.0)
            issues.append({QStringLiteral("valueScale"),
                           QCoreApplication::translate("Modbus", "Correction: the scale must not be zero")});
        if (type == RegisterType::UInt16 || type == RegisterType::UInt32)
            issues.append({QStringLiteral("valueType"),
                           QCoreApplication::translate(
                               "Modbus", "Correction: type must be signed (corrections can be negative)")});
    }
    return issues;
}

std::unique_ptr<Device> ModbusFactory::create(DeviceKind kind, const QVariantMap& settings,
                                              const DeviceContext& context) {
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    if (kind == DeviceKind::DriveCurrent) return std::make_unique<ModbusDriveDevice>(values, context);
    if (kind == DeviceKind::CorrectionOutput) return std::make_unique<ModbusOutputDevice>(values, context);
    throw std::invalid_argument("the Modbus plugin makes drive-current readouts and correction outputs only");
}

}  // namespace tt::devices
