#include "devices/probe_mandrel/probe_mandrel_factory.h"

#include <QCoreApplication>

#include "devices/api/serial_settings.h"
#include "devices/probe_mandrel/serial_probe_device.h"

namespace tt::devices {

SettingsSchema ProbeMandrelFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::Probe) return {};
    SettingsSchema s = serialFields(115200);
    s << SettingField::integer(
        QStringLiteral("rateHz"), QCoreApplication::translate("ProbeMandrel", "Sample rate"), 200, 1, 1000,
        QCoreApplication::translate("ProbeMandrel", "Hz"),
        QCoreApplication::translate("ProbeMandrel", "The PLC applies the correction every 10 to 100 ms (paper 001)."));
    s << SettingField::integer(
        QStringLiteral("silenceTimeoutMs"), QCoreApplication::translate("ProbeMandrel", "Silence timeout"), 500, 50,
        10000, QCoreApplication::translate("ProbeMandrel", "ms"),
        QCoreApplication::translate("ProbeMandrel", "No data for this long: the probe is in error."));
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"),
                               QCoreApplication::translate("ProbeMandrel", "Command timeout"), 300, 20, 5000,
                               QCoreApplication::translate("ProbeMandrel", "ms"));
    return s;
}

std::unique_ptr<Device> ProbeMandrelFactory::create(DeviceKind kind, const QVariantMap& settings,
                                                    const DeviceContext& context) {
    if (kind != DeviceKind::Probe) throw std::invalid_argument("the probe-mandrel plugin makes probes only");
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    return std::make_unique<SerialProbeDevice>(values, context);
}

}  // namespace tt::devices
