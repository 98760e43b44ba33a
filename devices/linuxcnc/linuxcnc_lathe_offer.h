#pragma once

#include <QString>
#include <QVariantMap>

#include "devices/api/shaft_machine_offer.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"

namespace tt::devices::linuxcnc {

/// The LinuxCNC lathe's options from a LinuxCNC device's settings (linuxCncSchema(), or settingsFromUrl for
/// `linuxcnc://HOST:PORT`): the connection and the correction mode, its program written into `programFolder` (a
/// folder the LinuxCNC computer reads under the same path), TrueTurn pressing cycle start when `pressCycleStart`.
LinuxCncLatheOptions latheOptions(const QVariantMap& settings, const QString& programFolder, bool pressCycleStart);

/// The machine "LinuxCNC lathe" of those settings for the Run page and `trueturn simulate --cnc`: key
/// "linuxcnc-lathe:HOST:PORT", its time the wall clock (no adjustable speed). make() builds a LinuxCncLathe in the
/// calling thread (the loop's) and starts its session; it throws std::invalid_argument for a scenario without a
/// physical lathe or a program folder that does not exist.
ShaftMachineOffer linuxCncLatheOffer(const QVariantMap& settings, const QString& programFolder,
                                     bool pressCycleStart = true);

}  // namespace tt::devices::linuxcnc
