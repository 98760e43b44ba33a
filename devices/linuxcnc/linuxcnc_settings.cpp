#include "devices/linuxcnc/linuxcnc_settings.h"

#include <QCoreApplication>
#include <QUrl>
#include <stdexcept>

namespace tt::devices::linuxcnc {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("LinuxCnc", text);
}

SettingsSchema connectionFields() {
    SettingsSchema s;
    s << SettingField::text(QStringLiteral("host"), tr("Host"), QStringLiteral("127.0.0.1"),
                            tr("IP address or name of the LinuxCNC computer (its remote shell, linuxcncrsh)."));
    s << SettingField::integer(QStringLiteral("port"), tr("TCP port"), 5007, 1, 65535);
    s << SettingField::text(QStringLiteral("connectPassword"), tr("Connect password"), QStringLiteral("EMC"),
                            tr("linuxcncrsh --connectpw; sent in clear text."));
    s << SettingField::text(QStringLiteral("enablePassword"), tr("Enable password"), QStringLiteral("EMCTOO"),
                            tr("linuxcncrsh --enablepw: the right to command the machine; sent in clear text."));
    s << SettingField::text(QStringLiteral("clientName"), tr("Client name"), QStringLiteral("TrueTurn"),
                            tr("How TrueTurn introduces itself (one word)."));
    s << SettingField::integer(QStringLiteral("connectTimeoutMs"), tr("Connect timeout"), 2000, 100, 60000, tr("ms"));
    s << SettingField::integer(QStringLiteral("replyTimeoutMs"), tr("Reply timeout"), 3000, 100, 60000, tr("ms"),
                               tr("A reply, a mode change or an MDI line; the connection is reset without it."));
    s << SettingField::integer(QStringLiteral("joints"), tr("Joints to be homed"), 2, 1, 9, {},
                               tr("A lathe: 2 (X and Z)."));
    return s;
}

SettingsSchema correctionFields() {
    SettingsSchema s;
    s << SettingField::choice(
        QStringLiteral("mode"), tr("How the correction reaches the cut"),
        {{QStringLiteral("profile"), tr("Profile: the control-point corrections as numbered parameters")},
         {QStringLiteral("wear"), tr("Wear: one diameter correction as the tool's X wear")}},
        QStringLiteral("profile"));
    s << SettingField::integer(QStringLiteral("firstParameter"), tr("First parameter"), 500, 31, 4990, {},
                               tr("#500 .. #504 hold the corrections, #505 the part number they are for."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("profile")});
    s << SettingField::integer(QStringLiteral("toolNumber"), tr("Tool"), 1, 1, 99999);
    s << SettingField::integer(QStringLiteral("wearTool"), tr("Wear entry (tool number)"), 10001, 1, 99999, {},
                               tr("Its X wear is set by G10 L1; the part program applies it with G43.2 H<entry>."))
             .visibleWhen(QStringLiteral("mode"), {QStringLiteral("wear")});
    s << SettingField::choice(QStringLiteral("xMode"), tr("X words of the part program"),
                              {{QStringLiteral("diameter"), tr("Diameters (G7)")},
                               {QStringLiteral("radius"), tr("Radii (G8)")}},
                              QStringLiteral("diameter"));
    s << SettingField::choice(QStringLiteral("units"), tr("Units of the part program"),
                              {{QStringLiteral("mm"), tr("Millimetres (G21)")}, {QStringLiteral("inch"), tr("Inches (G20)")}},
                              QStringLiteral("mm"));
    s << SettingField::number(QStringLiteral("largestStepMm"), tr("Largest step"), 0.1, 0.0005, 5.0, tr("mm"), 4,
                              tr("Largest change of a correction from part to part (radial); larger is never written."));
    s << SettingField::number(QStringLiteral("largestTotalMm"), tr("Largest total"), 0.5, 0.001, 5.0, tr("mm"), 4,
                              tr("Largest correction (radial); larger is never written."));
    s << SettingField::text(QStringLiteral("programPath"), tr("Part program on the LinuxCNC computer"), QString(),
                            tr("Empty: the operator runs the parts; TrueTurn writes between them."));
    s << SettingField::boolean(QStringLiteral("pressCycleStart"), tr("TrueTurn presses cycle start"), false,
                               tr("Otherwise the operator presses it after TrueTurn has written the corrections."));
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
    c.clientName = v.value(QStringLiteral("clientName")).toString().simplified().replace(QLatin1Char(' '), QLatin1Char('_')).toStdString();
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
    return tr("LinuxCNC at %1:%2")
        .arg(settings.value(QStringLiteral("host")).toString())
        .arg(settings.value(QStringLiteral("port"), 5007).toInt());
}

}  // namespace tt::devices::linuxcnc
