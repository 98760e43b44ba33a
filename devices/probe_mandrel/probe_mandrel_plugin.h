#pragma once

#include <QObject>

#include "devices/probe_mandrel/probe_mandrel_factory.h"

namespace tt::devices {

/// The Qt plugin that exports ProbeMandrelFactory (libtrueturn_probe_mandrel.so).
class ProbeMandrelPlugin final : public QObject, public ProbeMandrelFactory {
    Q_OBJECT
    Q_PLUGIN_METADATA(IID TrueTurnDevicePlugin_iid)
    Q_INTERFACES(tt::devices::DevicePlugin)
};

}  // namespace tt::devices
