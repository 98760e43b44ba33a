#pragma once

#include <QObject>

#include "devices/cnc_output/gcode_output_factory.h"

namespace tt::devices {

/// The Qt plugin that exports GCodeOutputFactory (libtrueturn_cnc_output.so).
class GCodeOutputPlugin final : public QObject, public GCodeOutputFactory {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)
};

}  // namespace tt::devices
