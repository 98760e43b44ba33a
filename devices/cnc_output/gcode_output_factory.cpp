#include "devices/cnc_output/gcode_output_factory.h"

#include <QDir>

#include "devices/cnc_output/gcode_file_output.h"

namespace tt::devices {

SettingsSchema GCodeOutputFactory::settingsSchema(DeviceKind kind) const {
    if (kind != DeviceKind::CorrectionOutput) return {};
    const GCodeJob d;
    return {
        SettingField::folder(QStringLiteral("folder"), QStringLiteral("Folder"), QDir::homePath(),
                             QStringLiteral("Where the CNC picks up its programs (network share, DNC folder).")),
        SettingField::text(QStringLiteral("fileName"), QStringLiteral("File name"), QStringLiteral("part-{part}.nc"),
                           QStringLiteral("{part} becomes the part number.")),
        SettingField::number(QStringLiteral("nominalDiameterMm"), QStringLiteral("Nominal diameter"),
                             d.nominalDiameterMm, 0.5, 2000.0, QStringLiteral("mm")),
        SettingField::number(QStringLiteral("feedMmPerRev"), QStringLiteral("Finishing feed"), d.feedMmPerRev, 0.01,
                             5.0, QStringLiteral("mm/rev")),
        SettingField::integer(QStringLiteral("spindleRpm"), QStringLiteral("Spindle speed"), d.spindleRpm, 0, 10000,
                              QStringLiteral("rpm"), QStringLiteral("0 leaves the spindle to the main program.")),
        SettingField::choice(QStringLiteral("xMode"), QStringLiteral("X words"),
                             {{QStringLiteral("diameter"), QStringLiteral("Diameters (diameter mode)")},
                              {QStringLiteral("radius"), QStringLiteral("Radii (radius mode)")}},
                             QStringLiteral("diameter")),
        SettingField::boolean(QStringLiteral("emitModeCode"), QStringLiteral("Write G7/G8"), d.emitModeCode,
                              QStringLiteral("For controls that select the X mode by G-code (LinuxCNC).")),
        SettingField::number(QStringLiteral("zOriginMm"), QStringLiteral("Machine Z of the part's left end"),
                             d.zOriginMm, -5000.0, 5000.0, QStringLiteral("mm")),
        SettingField::choice(QStringLiteral("zDirection"), QStringLiteral("Z direction along the part"),
                             {{QStringLiteral("-1"), QStringLiteral("Towards the chuck is -Z")},
                              {QStringLiteral("+1"), QStringLiteral("Towards the chuck is +Z")}},
                             QStringLiteral("-1")),
        SettingField::number(QStringLiteral("clearanceMm"), QStringLiteral("Clearance"), d.clearanceMm, 0.1, 100.0,
                             QStringLiteral("mm")),
        SettingField::integer(QStringLiteral("toolNumber"), QStringLiteral("Tool"), d.toolNumber, 1, 99),
        SettingField::integer(QStringLiteral("programNumber"), QStringLiteral("Program number"), d.programNumber, 1,
                              9999),
        SettingField::number(QStringLiteral("maxCorrectionMm"), QStringLiteral("Correction limit"), d.maxCorrectionMm,
                             0.001, 5.0, QStringLiteral("mm"), 3,
                             QStringLiteral("A path with a larger correction is refused, never written.")),
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
