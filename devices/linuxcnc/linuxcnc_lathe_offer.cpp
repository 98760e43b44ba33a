#include "devices/linuxcnc/linuxcnc_lathe_offer.h"

#include <QCoreApplication>

#include "devices/linuxcnc/linuxcnc_settings.h"

namespace tt::devices::linuxcnc {

LinuxCncLatheOptions latheOptions(const QVariantMap& settings, const QString& programFolder, bool pressCycleStart) {
    LinuxCncLatheOptions o;
    o.session = sessionSettings(settings);
    o.programFolder = programFolder.toStdString();
    o.pressCycleStart = pressCycleStart;
    return o;
}

ShaftMachineOffer linuxCncLatheOffer(const QVariantMap& settings, const QString& programFolder, bool pressCycleStart) {
    const LinuxCncLatheOptions options = latheOptions(settings, programFolder, pressCycleStart);
    ShaftMachineOffer offer;
    offer.key = QStringLiteral("linuxcnc-lathe:%1:%2")
                    .arg(QString::fromStdString(options.session.controller.endpoint.host))
                    .arg(options.session.controller.endpoint.port);
    offer.name = QCoreApplication::translate("LinuxCnc", "LinuxCNC lathe (%1)").arg(endpointText(settings));
    offer.description = QCoreApplication::translate(
        "LinuxCnc",
        "LinuxCNC machines every part; the simulated shaft's physics is applied to the path LinuxCNC executed and "
        "the simulated micrometer measures it; TrueTurn writes the corrections into LinuxCNC between parts.");
    offer.adjustableSpeed = false;
    offer.make = [options](const core::ShaftScenario& scenario, std::uint64_t seed) {
        return std::make_unique<LinuxCncLathe>(scenario, seed, options);
    };
    return offer;
}

}  // namespace tt::devices::linuxcnc
