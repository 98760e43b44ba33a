#include "devices/simulator/simulator_settings.h"

namespace tt::devices {

SettingsSchema simulatedGaugeSchema() {
    SettingsSchema s = gaugeFormatFields();
    s << SettingField::number(
        QStringLiteral("nominalDiameterMm"), QStringLiteral("Diameter measured"), 27.0, 1.0, 2000.0,
        QStringLiteral("mm"), 3,
        QStringLiteral("Stand-alone: every reading is this diameter (plus noise when switched on)."));
    s << SettingField::integer(QStringLiteral("decimals"), QStringLiteral("Resolution, decimals"), 3, 2, 5, {},
                               QStringLiteral("3 = 0.001 mm, the micrometer of paper 000."));
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"), QStringLiteral("Reply timeout"), 1000, 100, 10000,
                               QStringLiteral("ms"));
    return s;
}

SettingsSchema simulatedProbeSchema() {
    return {
        SettingField::integer(QStringLiteral("rateHz"), QStringLiteral("Sample rate"), 200, 1, 1000,
                              QStringLiteral("Hz")),
        SettingField::number(QStringLiteral("deflection1Mm"), QStringLiteral("Deflection, plane 1"), 0.020, -0.15, 0.15,
                             QStringLiteral("mm"), 4, QStringLiteral("Stand-alone: constant bending of the bar.")),
        SettingField::number(QStringLiteral("deflection2Mm"), QStringLiteral("Deflection, plane 2"), -0.005, -0.15,
                             0.15, QStringLiteral("mm"), 4),
        SettingField::integer(QStringLiteral("silenceTimeoutMs"), QStringLiteral("Silence timeout"), 500, 50, 10000,
                              QStringLiteral("ms")),
    };
}

SettingsSchema simulatedDriveSchema() {
    return {
        SettingField::integer(QStringLiteral("pollMs"), QStringLiteral("Polling period"), 20, 10, 100,
                              QStringLiteral("ms")),
        SettingField::number(QStringLiteral("amplitudeMm"), QStringLiteral("Oscillation amplitude"), 0.02, 0.005, 0.05,
                             QStringLiteral("mm"), 3,
                             QStringLiteral("Paper 001: 0.005 to 0.05 mm, inside the tolerance.")),
        SettingField::number(QStringLiteral("periodS"), QStringLiteral("Oscillation period"), 1.0, 0.2, 2.0,
                             QStringLiteral("s"), 2, QStringLiteral("Paper 001: 0.2 to 2 s.")),
        SettingField::number(QStringLiteral("frictionCurrentA"), QStringLiteral("Friction current"), 2.0, 0.0, 50.0,
                             QStringLiteral("A"), 2),
        SettingField::number(QStringLiteral("cuttingCurrentA"), QStringLiteral("Cutting current"), 0.6, -50.0, 50.0,
                             QStringLiteral("A"), 2),
    };
}

SettingsSchema simulatedOutputSchema() {
    return {
        SettingField::number(QStringLiteral("maxCorrectionMm"), QStringLiteral("Correction limit"), 0.5, 0.001, 5.0,
                             QStringLiteral("mm"), 3, QStringLiteral("Larger corrections are refused.")),
    };
}

}  // namespace tt::devices
