#include "devices/simulator/simulator_settings.h"

#include <QCoreApplication>

namespace tt::devices {

SettingsSchema simulatedGaugeSchema() {
    SettingsSchema s = gaugeFormatFields();
    s << SettingField::number(
        QStringLiteral("nominalDiameterMm"), QCoreApplication::translate("Simulator", "Diameter measured"), 27.0, 1.0,
        2000.0, QCoreApplication::translate("Simulator", "mm"), 3,
        QCoreApplication::translate("Simulator",
                                    "Stand-alone: every reading is this diameter (plus noise when switched on)."));
    s << SettingField::integer(QStringLiteral("decimals"),
                               QCoreApplication::translate("Simulator", "Resolution, decimals"), 3, 2, 5, {},
                               QCoreApplication::translate("Simulator", "3 = 0.001 mm, the micrometer of paper 000."));
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"),
                               QCoreApplication::translate("Simulator", "Reply timeout"), 1000, 100, 10000,
                               QCoreApplication::translate("Simulator", "ms"));
    return s;
}

SettingsSchema simulatedProbeSchema() {
    return {
        SettingField::integer(QStringLiteral("rateHz"), QCoreApplication::translate("Simulator", "Sample rate"), 200, 1,
                              1000, QCoreApplication::translate("Simulator", "Hz")),
        SettingField::number(QStringLiteral("deflection1Mm"),
                             QCoreApplication::translate("Simulator", "Deflection, plane 1"), 0.020, -0.15, 0.15,
                             QCoreApplication::translate("Simulator", "mm"), 4,
                             QCoreApplication::translate("Simulator", "Stand-alone: constant bending of the bar.")),
        SettingField::number(QStringLiteral("deflection2Mm"),
                             QCoreApplication::translate("Simulator", "Deflection, plane 2"), -0.005, -0.15, 0.15,
                             QCoreApplication::translate("Simulator", "mm"), 4),
        SettingField::integer(QStringLiteral("silenceTimeoutMs"),
                              QCoreApplication::translate("Simulator", "Silence timeout"), 500, 50, 10000,
                              QCoreApplication::translate("Simulator", "ms")),
        SettingField::boolean(
            QStringLiteral("stand"), QCoreApplication::translate("Simulator", "On a calibration stand"), true,
            QCoreApplication::translate("Simulator", "A screw jack bends the bar for the probe linearisation.")),
    };
}

SettingsSchema simulatedDriveSchema() {
    return {
        SettingField::integer(QStringLiteral("pollMs"), QCoreApplication::translate("Simulator", "Polling period"), 20,
                              10, 100, QCoreApplication::translate("Simulator", "ms")),
        SettingField::number(
            QStringLiteral("amplitudeMm"), QCoreApplication::translate("Simulator", "Oscillation amplitude"), 0.02,
            0.005, 0.05, QCoreApplication::translate("Simulator", "mm"), 3,
            QCoreApplication::translate("Simulator", "Paper 001: 0.005 to 0.05 mm, inside the tolerance.")),
        SettingField::number(QStringLiteral("periodS"), QCoreApplication::translate("Simulator", "Oscillation period"),
                             1.0, 0.2, 2.0, QCoreApplication::translate("Simulator", "s"), 2,
                             QCoreApplication::translate("Simulator", "Paper 001: 0.2 to 2 s.")),
        SettingField::number(QStringLiteral("frictionCurrentA"),
                             QCoreApplication::translate("Simulator", "Friction current"), 2.0, 0.0, 50.0,
                             QCoreApplication::translate("Simulator", "A"), 2),
        SettingField::number(QStringLiteral("cuttingCurrentA"),
                             QCoreApplication::translate("Simulator", "Cutting current"), 0.6, -50.0, 50.0,
                             QCoreApplication::translate("Simulator", "A"), 2),
        SettingField::boolean(QStringLiteral("stand"),
                              QCoreApplication::translate("Simulator", "On a calibration stand"), true,
                              QCoreApplication::translate(
                                  "Simulator", "A hydraulic jack applies the known loads of the k_p calibration.")),
    };
}

SettingsSchema simulatedOutputSchema() {
    return {
        SettingField::number(QStringLiteral("maxCorrectionMm"),
                             QCoreApplication::translate("Simulator", "Correction limit"), 0.5, 0.001, 5.0,
                             QCoreApplication::translate("Simulator", "mm"), 3,
                             QCoreApplication::translate("Simulator", "Larger corrections are refused.")),
    };
}

}  // namespace tt::devices
