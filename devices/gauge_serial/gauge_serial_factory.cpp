#include "devices/gauge_serial/gauge_serial_factory.h"

#include <QCoreApplication>

#include "devices/api/gauge_settings.h"
#include "devices/api/serial_settings.h"
#include "devices/gauge_serial/serial_gauge_device.h"
#include "devices/parsers/request_string.h"

namespace tt::devices {

SettingsSchema GaugeSerialFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::Gauge) return {};
    SettingsSchema s = serialFields(9600);
    s << gaugeFormatFields();
    s << SettingField::choice(
        QStringLiteral("mode"), QCoreApplication::translate("SerialGauge", "Readings"),
        {{QStringLiteral("push"), QCoreApplication::translate("SerialGauge", "Sent with the DATA button")},
         {QStringLiteral("polled"), QCoreApplication::translate("SerialGauge", "Asked for by TrueTurn")}},
        QStringLiteral("push"));
    s << SettingField::text(
             QStringLiteral("request"), QCoreApplication::translate("SerialGauge", "Request string"),
             QStringLiteral("\\r"),
             QCoreApplication::translate("SerialGauge",
                                         "Sent to ask for a reading, as the interface's manual gives it; "
                                         "escapes \\r \\n \\xNN."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("polled")});
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"),
                               QCoreApplication::translate("SerialGauge", "Reply timeout"), 1000, 50, 10000,
                               QCoreApplication::translate("SerialGauge", "ms"))
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
                           QCoreApplication::translate(
                               "SerialGauge", "Request string: '%1' is empty or has a bad escape (use \\r, \\n, \\xNN)")
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
