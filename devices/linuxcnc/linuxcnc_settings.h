#pragma once

#include <QString>
#include <QVariantMap>

#include "devices/api/settings_schema.h"
#include "devices/linuxcnc/linuxcnc_session.h"

namespace tt::devices::linuxcnc {

/// The settings of a LinuxCNC device on the Devices page: connection (host, port, connect and enable passwords,
/// client name, connect and reply timeouts, joints to be homed), the correction mode (profile: parameters from
/// firstParameter; wear: the X wear of wearTool), the tool, the part program's X mode and units, the largest
/// step and total of a correction, and the part cycle (the program on the LinuxCNC computer, whether TrueTurn
/// presses cycle start).
SettingsSchema linuxCncSchema();

/// The session settings of validated `settings` (defaults filled in).
SessionSettings sessionSettings(const QVariantMap& settings);

/// The settings of `linuxcnc://HOST[:PORT]` (port 5007 when absent) over the defaults, with the mode "profile"
/// or "wear". Throws std::invalid_argument naming the URL when it is not of that form.
QVariantMap settingsFromUrl(const QString& url, const QString& mode = QStringLiteral("profile"));

/// "LinuxCNC at 127.0.0.1:5007", for messages.
QString endpointText(const QVariantMap& settings);

}  // namespace tt::devices::linuxcnc
