#include "devices/cnc_output/gcode_output_factory.h"

#include <QCoreApplication>
#include <QDir>

#include "devices/cnc_output/gcode_file_output.h"

namespace tt::devices {

SettingsSchema GCodeOutputFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::CorrectionOutput) return {};
    const GCodeJob d;
    return {
        SettingField::folder(QStringLiteral("folder"), QCoreApplication::translate("GCodeOutput", "Folder"),
                             QDir::homePath(),
                             QCoreApplication::translate(
                                 "GCodeOutput", "Where the CNC picks up its programs (network share, DNC folder).")),
        SettingField::text(QStringLiteral("fileName"), QCoreApplication::translate("GCodeOutput", "File name"),
                           QStringLiteral("part-{part}.nc"),
                           QCoreApplication::translate("GCodeOutput", "{part} becomes the part number.")),
        SettingField::number(QStringLiteral("nominalDiameterMm"),
                             QCoreApplication::translate("GCodeOutput", "Nominal diameter"), d.nominalDiameterMm, 0.5,
                             2000.0, QCoreApplication::translate("GCodeOutput", "mm")),
        SettingField::number(QStringLiteral("feedMmPerRev"),
                             QCoreApplication::translate("GCodeOutput", "Finishing feed"), d.feedMmPerRev, 0.01, 5.0,
                             QCoreApplication::translate("GCodeOutput", "mm/rev")),
        SettingField::integer(QStringLiteral("spindleRpm"), QCoreApplication::translate("GCodeOutput", "Spindle speed"),
                              d.spindleRpm, 0, 10000, QCoreApplication::translate("GCodeOutput", "rpm"),
                              QCoreApplication::translate("GCodeOutput", "0 leaves the spindle to the main program.")),
        SettingField::choice(
            QStringLiteral("xMode"), QCoreApplication::translate("GCodeOutput", "X words"),
            {{QStringLiteral("diameter"), QCoreApplication::translate("GCodeOutput", "Diameters (diameter mode)")},
             {QStringLiteral("radius"), QCoreApplication::translate("GCodeOutput", "Radii (radius mode)")}},
            QStringLiteral("diameter")),
        SettingField::boolean(
            QStringLiteral("emitModeCode"), QCoreApplication::translate("GCodeOutput", "Write G7/G8"), d.emitModeCode,
            QCoreApplication::translate("GCodeOutput", "For controls that select the X mode by G-code (LinuxCNC).")),
        SettingField::number(QStringLiteral("zOriginMm"),
                             QCoreApplication::translate("GCodeOutput", "Machine Z of the part's left end"),
                             d.zOriginMm, -5000.0, 5000.0, QCoreApplication::translate("GCodeOutput", "mm")),
        SettingField::choice(
            QStringLiteral("zDirection"), QCoreApplication::translate("GCodeOutput", "Z direction along the part"),
            {{QStringLiteral("-1"), QCoreApplication::translate("GCodeOutput", "Towards the chuck is -Z")},
             {QStringLiteral("+1"), QCoreApplication::translate("GCodeOutput", "Towards the chuck is +Z")}},
            QStringLiteral("-1")),
        SettingField::number(QStringLiteral("clearanceMm"), QCoreApplication::translate("GCodeOutput", "Clearance"),
                             d.clearanceMm, 0.1, 100.0, QCoreApplication::translate("GCodeOutput", "mm")),
        SettingField::integer(QStringLiteral("toolNumber"), QCoreApplication::translate("GCodeOutput", "Tool"),
                              d.toolNumber, 1, 99),
        SettingField::integer(QStringLiteral("programNumber"),
                              QCoreApplication::translate("GCodeOutput", "Program number"), d.programNumber, 1, 9999),
        SettingField::number(
            QStringLiteral("maxCorrectionMm"), QCoreApplication::translate("GCodeOutput", "Correction limit"),
            d.maxCorrectionMm, 0.001, 5.0, QCoreApplication::translate("GCodeOutput", "mm"), 3,
            QCoreApplication::translate("GCodeOutput", "A path with a larger correction is refused, never written.")),
    };
}

std::unique_ptr<Device> GCodeOutputFactory::create(DeviceKind kind, const QVariantMap& settings,
                                                   const DeviceContext& context) {
    if (kind != DeviceKind::CorrectionOutput)
        throw std::invalid_argument("the G-code plugin makes correction outputs only");
    const QVariantMap values = withDefaults(settingsSchema(kind), settings);
    requireValidSettings(*this, kind, values);
    return std::make_unique<GCodeFileOutput>(values, context);
}

}  // namespace tt::devices
