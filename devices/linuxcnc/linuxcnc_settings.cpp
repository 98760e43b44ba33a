#include "devices/linuxcnc/linuxcnc_settings.h"

#include <QCoreApplication>
#include <QUrl>
#include <stdexcept>

namespace tt::devices::linuxcnc {

namespace {

SettingsSchema connectionFields() {
    SettingsSchema s;
    s << SettingField::text(
        QStringLiteral("host"), QCoreApplication::translate("LinuxCnc", "Host"), QStringLiteral("127.0.0.1"),
        QCoreApplication::translate("LinuxCnc",
                                    "IP address or name of the LinuxCNC computer (its remote shell, linuxcncrsh)."));
    s << SettingField::integer(QStringLiteral("port"), QCoreApplication::translate("LinuxCnc", "TCP port"), 5007, 1,
                               65535);
    s << SettingField::text(QStringLiteral("connectPassword"),
                            QCoreApplication::translate("LinuxCnc", "Connect password"), QStringLiteral("EMC"),
                            QCoreApplication::translate("LinuxCnc", "linuxcncrsh --connectpw; sent in clear text."));
    s << SettingField::text(
        QStringLiteral("enablePassword"), QCoreApplication::translate("LinuxCnc", "Enable password"),
        QStringLiteral("EMCTOO"),
        QCoreApplication::translate("LinuxCnc",
                                    "linuxcncrsh --enablepw: the right to command the machine; sent in clear text."));
    s << SettingField::text(QStringLiteral("clientName"), QCoreApplication::translate("LinuxCnc", "Client name"),
                            QStringLiteral("TrueTurn"),
                            QCoreApplication::translate("LinuxCnc", "How TrueTurn introduces itself (one word)."));
    s << SettingField::integer(QStringLiteral("connectTimeoutMs"),
                               QCoreApplication::translate("LinuxCnc", "Connect timeout"), 2000, 100, 60000,
                               QCoreApplication::translate("LinuxCnc", "ms"));
    s << SettingField::integer(
        QStringLiteral("replyTimeoutMs"), QCoreApplication::translate("LinuxCnc", "Reply timeout"), 3000, 100, 60000,
        QCoreApplication::translate("LinuxCnc", "ms"),
        QCoreApplication::translate("LinuxCnc",
                                    "A reply, a mode change or an MDI line; the connection is reset without it."));
    s << SettingField::integer(QStringLiteral("joints"), QCoreApplication::translate("LinuxCnc", "Joints to be homed"),
                               2, 1, 9, {}, QCoreApplication::translate("LinuxCnc", "A lathe: 2 (X and Z)."));
    return s;
}

SettingsSchema correctionFields() {
    SettingsSchema s;
    s << SettingField::choice(
        QStringLiteral("mode"), QCoreApplication::translate("LinuxCnc", "How the correction reaches the cut"),
        {{QStringLiteral("profile"),
          QCoreApplication::translate("LinuxCnc", "Profile: the control-point corrections as numbered parameters")},
         {QStringLiteral("wear"),
          QCoreApplication::translate("LinuxCnc", "Wear: one diameter correction as the tool's X wear")}},
        QStringLiteral("profile"));
    s << SettingField::integer(QStringLiteral("firstParameter"),
                               QCoreApplication::translate("LinuxCnc", "First parameter"), 500, 31, 4990, {},
                               QCoreApplication::translate(
                                   "LinuxCnc", "#500 .. #504 hold the corrections, #505 the part number they are for."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("profile")});
    s << SettingField::integer(QStringLiteral("toolNumber"), QCoreApplication::translate("LinuxCnc", "Tool"), 1, 1,
                               99999);
    s << SettingField::integer(
             QStringLiteral("wearTool"), QCoreApplication::translate("LinuxCnc", "Wear entry (tool number)"), 10001, 1,
             99999, {},
             QCoreApplication::translate(
                 "LinuxCnc", "Its X wear is set by G10 L1; the part program applies it with G43.2 H<entry>."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("wear")});
    s << SettingField::choice(QStringLiteral("xMode"),
                              QCoreApplication::translate("LinuxCnc", "X words of the part program"),
                              {{QStringLiteral("diameter"), QCoreApplication::translate("LinuxCnc", "Diameters (G7)")},
                               {QStringLiteral("radius"), QCoreApplication::translate("LinuxCnc", "Radii (G8)")}},
                              QStringLiteral("diameter"));
    s << SettingField::choice(QStringLiteral("units"),
                              QCoreApplication::translate("LinuxCnc", "Units of the part program"),
                              {{QStringLiteral("mm"), QCoreApplication::translate("LinuxCnc", "Millimetres (G21)")},
                               {QStringLiteral("inch"), QCoreApplication::translate("LinuxCnc", "Inches (G20)")}},
                              QStringLiteral("mm"));
    s << SettingField::number(
        QStringLiteral("largestStepMm"), QCoreApplication::translate("LinuxCnc", "Largest step"), 0.1, 0.0005, 5.0,
        QCoreApplication::translate("LinuxCnc", "mm"), 4,
        QCoreApplication::translate(
            "LinuxCnc", "Largest change of a correction from part to part (radial); larger is never written."));
    s << SettingField::number(
        QStringLiteral("largestTotalMm"), QCoreApplication::translate("LinuxCnc", "Largest total"), 0.5, 0.001, 5.0,
        QCoreApplication::translate("LinuxCnc", "mm"), 4,
        QCoreApplication::translate("LinuxCnc", "Largest correction (radial); larger is never written."));
    s << SettingField::text(
        QStringLiteral("programPath"), QCoreApplication::translate("LinuxCnc", "Part program on the LinuxCNC computer"),
        QString(),
        QCoreApplication::translate("LinuxCnc", "Empty: the operator runs the parts; TrueTurn writes between them."));
    s << SettingField::boolean(
        QStringLiteral("pressCycleStart"), QCoreApplication::translate("LinuxCnc", "TrueTurn presses cycle start"),
        false,
        QCoreApplication::translate("LinuxCnc",
                                    "Otherwise the operator presses it after TrueTurn has written the corrections."));
    return s;
}

}  // namespace

SettingsSchema linuxCncSchema() {
    SettingsSchema s = connectionFields();
    s << correctionFields();
    return s;
}

SessionSettings sessionSettings(const QVariantMap& given) {
    const QVariantMap v = withDefaults(linuxCncSchema(), given);
    SessionSettings s;
    ControllerOptions& c = s.controller;
    c.endpoint = {v.value(QStringLiteral("host")).toString().trimmed().toStdString(),
                  v.value(QStringLiteral("port")).toInt()};
    c.connectPassword = v.value(QStringLiteral("connectPassword")).toString().toStdString();
    c.enablePassword = v.value(QStringLiteral("enablePassword")).toString().toStdString();
    c.clientName = v.value(QStringLiteral("clientName"))
                       .toString()
                       .simplified()
                       .replace(QLatin1Char(' '), QLatin1Char('_'))
                       .toStdString();
    c.connectTimeoutMs = v.value(QStringLiteral("connectTimeoutMs")).toInt();
    c.replyTimeoutMs = v.value(QStringLiteral("replyTimeoutMs")).toInt();
    c.joints = v.value(QStringLiteral("joints")).toInt();
    CorrectionSettings& k = s.corrections;
    k.mode = correctionModeFromName(v.value(QStringLiteral("mode")).toString().toStdString());
    k.firstParameter = v.value(QStringLiteral("firstParameter")).toInt();
    k.toolNumber = v.value(QStringLiteral("toolNumber")).toInt();
    k.wearTool = v.value(QStringLiteral("wearTool")).toInt();
    k.conventions.diameterMode = v.value(QStringLiteral("xMode")).toString() != QLatin1String("radius");
    k.conventions.inch = v.value(QStringLiteral("units")).toString() == QLatin1String("inch");
    k.largestStepMm = v.value(QStringLiteral("largestStepMm")).toDouble();
    k.largestTotalMm = v.value(QStringLiteral("largestTotalMm")).toDouble();
    return s;
}

QVariantMap settingsFromUrl(const QString& url, const QString& mode) {
    const QUrl parsed(url, QUrl::StrictMode);
    if (!parsed.isValid() || parsed.scheme() != QLatin1String("linuxcnc") || parsed.host().isEmpty() ||
        !parsed.path().isEmpty() || parsed.hasQuery())
        throw std::invalid_argument("'" + url.toStdString() + "' is not linuxcnc://HOST[:PORT]");
    if (mode != QLatin1String("profile") && mode != QLatin1String("wear"))
        throw std::invalid_argument("the LinuxCNC correction mode '" + mode.toStdString() + "' is not profile or wear");
    QVariantMap v = withDefaults(linuxCncSchema(), {});
    v.insert(QStringLiteral("host"), parsed.host());
    v.insert(QStringLiteral("port"), parsed.port(5007));
    v.insert(QStringLiteral("mode"), mode);
    return v;
}

QString endpointText(const QVariantMap& settings) {
    return QCoreApplication::translate("LinuxCnc", "LinuxCNC at %1:%2")
        .arg(settings.value(QStringLiteral("host")).toString())
        .arg(settings.value(QStringLiteral("port"), 5007).toInt());
}

}  // namespace tt::devices::linuxcnc
