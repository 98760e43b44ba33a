#include "devices/gauge_serial/gauge_serial_factory.h"

#include "devices/api/gauge_settings.h"
#include "devices/api/serial_settings.h"
#include "devices/gauge_serial/serial_gauge_device.h"
#include "devices/parsers/request_string.h"

namespace tt::devices {

SettingsSchema GaugeSerialFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::Gauge) return {};
    SettingsSchema s = serialFields(9600);
    s << gaugeFormatFields();
    s << SettingField::choice(QStringLiteral("mode"), QStringLiteral("Readings"),
                              {{QStringLiteral("push"), QStringLiteral("Sent with the DATA button")},
                               {QStringLiteral("polled"), QStringLiteral("Asked for by TrueTurn")}},
                              QStringLiteral("push"));
    s << SettingField::text(QStringLiteral("request"), QStringLiteral("Request string"), QStringLiteral("\\r"),
                            QStringLiteral("Sent to ask for a reading, as the interface's manual gives it; "
                                           "escapes \\r \\n \\xNN."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("polled")});
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"), QStringLiteral("Reply timeout"), 1000, 50, 10000,
                               QStringLiteral("ms"))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("polled")});
    return s;
}

QList<SettingIssue> GaugeSerialFactory::validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const {
    QList<SettingIssue> issues = DevicePlugin::validate(kind, settings, depth);
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    if (values.value(QStringLiteral("mode")).toString() == QLatin1String("polled")) {
        const auto request = unescapeRequest(values.value(QStringLiteral("request")).toString().toStdString());
        if (!request || request->empty())
            issues.append({QStringLiteral("request"),
                           QStringLiteral("Request string: '%1' is empty or has a bad escape (use \\r, \\n, \\xNN)")
                               .arg(values.value(QStringLiteral("request")).toString())});
    }
    return issues;
}

std::unique_ptr<Device> GaugeSerialFactory::create(DeviceKind kind, const QVariantMap& settings,
                                                   const DeviceContext& context) {
    if (kind != DeviceKind::Gauge) throw std::invalid_argument("the serial gauge plugin makes gauges only");
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    return std::make_unique<SerialGaugeDevice>(values, context);
}

}  // namespace tt::devices
