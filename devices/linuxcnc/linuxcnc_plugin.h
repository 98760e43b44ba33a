#pragma once

#include <QObject>

#include "devices/linuxcnc/linuxcnc_factory.h"

namespace tt::devices::linuxcnc {

/// The Qt plugin that exports LinuxCncFactory (libtrueturn_linuxcnc.so).
class LinuxCncPlugin final : public QObject, public LinuxCncFactory {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)
};

}  // namespace tt::devices::linuxcnc
