#include "devices/linuxcnc/linuxcnc_factory.h"

#include <QDir>
#include <QFileInfo>

#include "devices/linuxcnc/linuxcnc_lathe_offer.h"
#include "devices/linuxcnc/linuxcnc_output_device.h"
#include "devices/linuxcnc/linuxcnc_settings.h"

namespace tt::devices::linuxcnc {

SettingsSchema LinuxCncFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::CorrectionOutput) return {};
    return linuxCncSchema();
}

QList<SettingIssue> LinuxCncFactory::validate(DeviceKind kind, const QVariantMap& settings, Validation depth) const {
    QList<SettingIssue> issues = DevicePlugin::validate(kind, settings, depth);
    const QVariantMap v = withDefaults(settingsSchema(kind), settings);
    if (v.value(QStringLiteral("host")).toString().trimmed().isEmpty())
        issues.append(
            {QStringLiteral("host"),
             QCoreApplication::translate("LinuxCnc", "Host: enter the IP address or name of the LinuxCNC computer")});
    for (const char* key : {"connectPassword", "enablePassword", "clientName"}) {
        const QString value = v.value(QLatin1String(key)).toString();
        if (value.isEmpty() || value.contains(QLatin1Char(' ')))
            issues.append(
                {QLatin1String(key), QCoreApplication::translate(
                                         "LinuxCnc", "%1: one word without spaces (the remote shell splits at spaces)")
                                         .arg(QLatin1String(key))});
    }
    if (v.value(QStringLiteral("largestStepMm")).toDouble() > v.value(QStringLiteral("largestTotalMm")).toDouble())
        issues.append({QStringLiteral("largestStepMm"),
                       QCoreApplication::translate("LinuxCnc", "Largest step: must not exceed the largest total")});
    const QString program = v.value(QStringLiteral("programPath")).toString().trimmed();
    if (!program.isEmpty() && !program.startsWith(QLatin1Char('/')))
        issues.append(
            {QStringLiteral("programPath"),
             QCoreApplication::translate("LinuxCnc", "Part program: an absolute path on the LinuxCNC computer")});
    return issues;
}

std::unique_ptr<Device> LinuxCncFactory::create(DeviceKind kind, const QVariantMap& settings,
                                                const DeviceContext& context) {
    if (kind != DeviceKind::CorrectionOutput)
        throw std::invalid_argument("the LinuxCNC plugin makes correction outputs only");
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    return std::make_unique<LinuxCncOutputDevice>(values, context);
}

QList<ShaftMachineOffer> LinuxCncFactory::deviceMachines(DeviceKind kind, const QVariantMap& settings) const {
    if (kind != DeviceKind::CorrectionOutput) return {};
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    const QString program = values.value(QStringLiteral("programPath")).toString().trimmed();
    const QString folder = program.isEmpty() ? deviceProgramFolder() : QFileInfo(program).absolutePath();
    return {linuxCncLatheOffer(values, folder, values.value(QStringLiteral("pressCycleStart"), true).toBool())};
}

QString deviceProgramFolder() {
    const QString folder = QDir::temp().filePath(QStringLiteral("trueturn-linuxcnc"));
    QDir().mkpath(folder);
    return folder;
}

}  // namespace tt::devices::linuxcnc
