#include "devices/api/gauge_settings.h"

#include <QCoreApplication>

namespace tt::devices {

namespace {

LengthUnit unitOf(const QVariantMap& settings, const QString& key) {
    return settings.value(key).toString() == QLatin1String("in") ? LengthUnit::Inch : LengthUnit::Millimetre;
}

QList<SettingChoice> unitChoices() {
    return {{QStringLiteral("mm"), QCoreApplication::translate("DeviceSettings", "Millimetres")},
            {QStringLiteral("in"), QCoreApplication::translate("DeviceSettings", "Inches")}};
}

}  // namespace

SettingsSchema gaugeFormatFields() {
    SettingsSchema fields;
    fields << SettingField::choice(
        QStringLiteral("format"), QCoreApplication::translate("DeviceSettings", "Output format"),
        {{QStringLiteral("ascii"), QCoreApplication::translate("DeviceSettings", "ASCII data cable (01A+00026.812)")},
         {QStringLiteral("digimatic-nibbles"), QCoreApplication::translate("DeviceSettings", "Digimatic, 13 nibbles")},
         {QStringLiteral("digimatic-hex"),
          QCoreApplication::translate("DeviceSettings", "Digimatic, hexadecimal text")}},
        QStringLiteral("ascii"),
        QCoreApplication::translate("DeviceSettings", "What the data cable or interface sends."));
    fields << SettingField::choice(
                  QStringLiteral("instrumentUnit"), QCoreApplication::translate("DeviceSettings", "Instrument unit"),
                  unitChoices(), QStringLiteral("mm"),
                  QCoreApplication::translate("DeviceSettings",
                                              "The unit the micrometer displays; the ASCII format does not say."))
                  .visibleWhen(QStringLiteral("format"), {QStringLiteral("ascii")});
    fields << SettingField::choice(
        QStringLiteral("jobUnit"), QCoreApplication::translate("DeviceSettings", "Job unit"), unitChoices(),
        QStringLiteral("mm"),
        QCoreApplication::translate("DeviceSettings",
                                    "Readings in another unit are refused, never converted silently."));
    return fields;
}

GaugeFormat gaugeFormat(const QVariantMap& settings) {
    const QString format = settings.value(QStringLiteral("format")).toString();
    if (format == QLatin1String("digimatic-nibbles")) return GaugeFormat::DigimaticNibbles;
    if (format == QLatin1String("digimatic-hex")) return GaugeFormat::DigimaticHex;
    return GaugeFormat::Ascii;
}

LengthUnit instrumentUnit(const QVariantMap& settings) {
    return unitOf(settings, QStringLiteral("instrumentUnit"));
}

LengthUnit jobUnit(const QVariantMap& settings) {
    return unitOf(settings, QStringLiteral("jobUnit"));
}

}  // namespace tt::devices
