#include "devices/modbus/modbus_settings.h"

#include <QCoreApplication>

#include "devices/api/serial_settings.h"

namespace tt::devices {

using namespace modbus;

SettingsSchema modbusConnectionFields() {
    SettingsSchema s;
    s << SettingField::choice(QStringLiteral("transport"), QCoreApplication::translate("Modbus", "Connection"),
                              {{QStringLiteral("tcp"), QCoreApplication::translate("Modbus", "Modbus TCP (Ethernet)")},
                               {QStringLiteral("rtu"), QCoreApplication::translate("Modbus", "Modbus RTU (serial)")}},
                              QStringLiteral("tcp"));
    s << SettingField::text(QStringLiteral("host"), QCoreApplication::translate("Modbus", "Host"),
                            QStringLiteral("192.168.0.10"),
                            QCoreApplication::translate("Modbus", "IP address or name of the drive or PLC."))
             .visibleWhen(QStringLiteral("transport"), {QStringLiteral("tcp")});
    s << SettingField::integer(QStringLiteral("tcpPort"), QCoreApplication::translate("Modbus", "TCP port"), 502, 1,
                               65535)
             .visibleWhen(QStringLiteral("transport"), {QStringLiteral("tcp")});
    for (SettingField f : serialFields(19200, 8, QStringLiteral("even")))
        s << f.visibleWhen(QStringLiteral("transport"), {QStringLiteral("rtu")});
    s << SettingField::integer(QStringLiteral("unitId"), QCoreApplication::translate("Modbus", "Unit id"), 1, 1, 247,
                               {}, QCoreApplication::translate("Modbus", "The server address of the drive or PLC."));
    s << SettingField::integer(QStringLiteral("timeoutMs"), QCoreApplication::translate("Modbus", "Reply timeout"), 200,
                               10, 5000, QCoreApplication::translate("Modbus", "ms"));
    s << SettingField::integer(QStringLiteral("retries"), QCoreApplication::translate("Modbus", "Retries"), 1, 0, 5);
    return s;
}

SettingsSchema registerFields(const QString& prefix, const QString& label, quint16 defaultAddress,
                              RegisterType defaultType, double defaultScale, const QStringList& units,
                              const QString& defaultUnit) {
    QList<SettingChoice> types;
    for (auto t : {RegisterType::Int16, RegisterType::UInt16, RegisterType::Int32, RegisterType::UInt32,
                   RegisterType::Float32}) {
        const QString key = QString::fromLatin1(typeKey(t).data());
        types.append({key, key});
    }
    SettingsSchema s;
    s << SettingField::choice(prefix + QStringLiteral("Table"),
                              QCoreApplication::translate("Modbus", "%1: registers").arg(label),
                              {{QStringLiteral("holding"), QCoreApplication::translate("Modbus", "Holding (4x)")},
                               {QStringLiteral("input"), QCoreApplication::translate("Modbus", "Input (3x)")}},
                              QStringLiteral("holding"));
    s << SettingField::integer(prefix + QStringLiteral("Address"),
                               QCoreApplication::translate("Modbus", "%1: address").arg(label), defaultAddress, 0,
                               65535, {}, QCoreApplication::translate("Modbus", "Zero-based protocol address."));
    s << SettingField::choice(prefix + QStringLiteral("Type"),
                              QCoreApplication::translate("Modbus", "%1: type").arg(label), types,
                              QString::fromLatin1(typeKey(defaultType).data()));
    s << SettingField::choice(prefix + QStringLiteral("WordOrder"),
                              QCoreApplication::translate("Modbus", "%1: word order").arg(label),
                              {{QStringLiteral("high-first"), QCoreApplication::translate("Modbus", "High word first")},
                               {QStringLiteral("low-first"), QCoreApplication::translate("Modbus", "Low word first")}},
                              QStringLiteral("high-first"));
    s << SettingField::number(prefix + QStringLiteral("Scale"),
                              QCoreApplication::translate("Modbus", "%1: scale").arg(label), defaultScale, -1e6, 1e6,
                              QCoreApplication::translate("Modbus", "per count"), 6,
                              QCoreApplication::translate("Modbus", "Value = register x scale (in the unit below)."));
    if (!units.isEmpty()) {
        QList<SettingChoice> choices;
        for (const QString& u : units)
            choices.append({u, u});
        s << SettingField::choice(prefix + QStringLiteral("Unit"),
                                  QCoreApplication::translate("Modbus", "%1: unit").arg(label), choices,
                                  defaultUnit.isEmpty() ? units.front() : defaultUnit);
    }
    return s;
}

RegisterSpec registerSpec(const QVariantMap& settings, const QString& prefix) {
    RegisterSpec spec;
    spec.name = prefix.toStdString();
    spec.table = tableFromKey(settings.value(prefix + QStringLiteral("Table")).toString().toStdString())
                     .value_or(RegisterTable::Holding);
    spec.address = static_cast<std::uint16_t>(settings.value(prefix + QStringLiteral("Address")).toUInt());
    spec.type = typeFromKey(settings.value(prefix + QStringLiteral("Type")).toString().toStdString())
                    .value_or(RegisterType::Int16);
    spec.order = wordOrderFromKey(settings.value(prefix + QStringLiteral("WordOrder")).toString().toStdString())
                     .value_or(WordOrder::HighWordFirst);
    spec.scale = settings.value(prefix + QStringLiteral("Scale"), 1.0).toDouble();
    return spec;
}

QString modbusEndpoint(const QVariantMap& settings) {
    const QString unit =
        QCoreApplication::translate("Modbus", "unit %1").arg(settings.value(QStringLiteral("unitId"), 1).toInt());
    if (settings.value(QStringLiteral("transport")).toString() == QLatin1String("rtu"))
        return QStringLiteral("%1, %2").arg(settings.value(QStringLiteral("port")).toString(), unit);
    return QStringLiteral("%1:%2, %3")
        .arg(settings.value(QStringLiteral("host")).toString())
        .arg(settings.value(QStringLiteral("tcpPort"), 502).toInt())
        .arg(unit);
}

}  // namespace tt::devices
