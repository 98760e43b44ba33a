#include "devices/modbus/modbus_settings.h"

#include "devices/api/serial_settings.h"

namespace tt::devices {

using namespace modbus;

SettingsSchema modbusConnectionFields() {
    SettingsSchema s;
    s << SettingField::choice(QStringLiteral("transport"), QStringLiteral("Connection"),
                              {{QStringLiteral("tcp"), QStringLiteral("Modbus TCP (Ethernet)")},
                               {QStringLiteral("rtu"), QStringLiteral("Modbus RTU (serial)")}},
                              QStringLiteral("tcp"));
    s << SettingField::text(QStringLiteral("host"), QStringLiteral("Host"), QStringLiteral("192.168.0.10"),
                            QStringLiteral("IP address or name of the drive or PLC."))
             .visibleWhen(QStringLiteral("transport"), {QStringLiteral("tcp")});
    s << SettingField::integer(QStringLiteral("tcpPort"), QStringLiteral("TCP port"), 502, 1, 65535)
             .visibleWhen(QStringLiteral("transport"), {QStringLiteral("tcp")});
    for (SettingField f : serialFields(19200, 8, QStringLiteral("even")))
        s << f.visibleWhen(QStringLiteral("transport"), {QStringLiteral("rtu")});
    s << SettingField::integer(QStringLiteral("unitId"), QStringLiteral("Unit id"), 1, 1, 247, {},
                               QStringLiteral("The server address of the drive or PLC."));
    s << SettingField::integer(QStringLiteral("timeoutMs"), QStringLiteral("Reply timeout"), 200, 10, 5000,
                               QStringLiteral("ms"));
    s << SettingField::integer(QStringLiteral("retries"), QStringLiteral("Retries"), 1, 0, 5);
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
    s << SettingField::choice(prefix + QStringLiteral("Table"), label + QStringLiteral(": registers"),
                              {{QStringLiteral("holding"), QStringLiteral("Holding (4x)")},
                               {QStringLiteral("input"), QStringLiteral("Input (3x)")}},
                              QStringLiteral("holding"));
    s << SettingField::integer(prefix + QStringLiteral("Address"), label + QStringLiteral(": address"), defaultAddress,
                               0, 65535, {}, QStringLiteral("Zero-based protocol address."));
    s << SettingField::choice(prefix + QStringLiteral("Type"), label + QStringLiteral(": type"), types,
                              QString::fromLatin1(typeKey(defaultType).data()));
    s << SettingField::choice(prefix + QStringLiteral("WordOrder"), label + QStringLiteral(": word order"),
                              {{QStringLiteral("high-first"), QStringLiteral("High word first")},
                               {QStringLiteral("low-first"), QStringLiteral("Low word first")}},
                              QStringLiteral("high-first"));
    s << SettingField::number(prefix + QStringLiteral("Scale"), label + QStringLiteral(": scale"), defaultScale, -1e6,
                              1e6, QStringLiteral("per count"), 6,
                              QStringLiteral("Value = register x scale (in the unit below)."));
    if (!units.isEmpty()) {
        QList<SettingChoice> choices;
        for (const QString& u : units)
            choices.append({u, u});
        s << SettingField::choice(prefix + QStringLiteral("Unit"), label + QStringLiteral(": unit"), choices,
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
    const QString unit = QStringLiteral("unit %1").arg(settings.value(QStringLiteral("unitId"), 1).toInt());
    if (settings.value(QStringLiteral("transport")).toString() == QLatin1String("rtu"))
        return QStringLiteral("%1, %2").arg(settings.value(QStringLiteral("port")).toString(), unit);
    return QStringLiteral("%1:%2, %3")
        .arg(settings.value(QStringLiteral("host")).toString())
        .arg(settings.value(QStringLiteral("tcpPort"), 502).toInt())
        .arg(unit);
}

}  // namespace tt::devices
