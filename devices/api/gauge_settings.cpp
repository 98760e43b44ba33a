#include "devices/api/gauge_settings.h"

namespace tt::devices {

namespace {

LengthUnit unitOf(const QVariantMap& settings, const QString& key) {
    return settings.value(key).toString() == QLatin1String("in") ? LengthUnit::Inch : LengthUnit::Millimetre;
}

QList<SettingChoice> unitChoices() {
    return {{QStringLiteral("mm"), QStringLiteral("Millimetres")}, {QStringLiteral("in"), QStringLiteral("Inches")}};
}

}  // namespace

SettingsSchema gaugeFormatFields() {
    SettingsSchema fields;
    fields << SettingField::choice(QStringLiteral("format"), QStringLiteral("Output format"),
                                   {{QStringLiteral("ascii"), QStringLiteral("ASCII data cable (01A+00026.812)")},
                                    {QStringLiteral("digimatic-nibbles"), QStringLiteral("Digimatic, 13 nibbles")},
                                    {QStringLiteral("digimatic-hex"), QStringLiteral("Digimatic, hexadecimal text")}},
                                   QStringLiteral("ascii"), QStringLiteral("What the data cable or interface sends."));
    fields << SettingField::choice(QStringLiteral("instrumentUnit"), QStringLiteral("Instrument unit"), unitChoices(),
                                   QStringLiteral("mm"),
                                   QStringLiteral("The unit the micrometer displays; the ASCII format does not say."))
                  .visibleWhen(QStringLiteral("format"), {QStringLiteral("ascii")});
    fields << SettingField::choice(QStringLiteral("jobUnit"), QStringLiteral("Job unit"), unitChoices(),
                                   QStringLiteral("mm"),
                                   QStringLiteral("Readings in another unit are refused, never converted silently."));
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
