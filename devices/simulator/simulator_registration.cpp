#include "devices/simulator/simulator_registration.h"

#include <QtPlugin>

// The simulator's static plugin (devices/simulator/simulator_plugin.h, compiled with QT_STATICPLUGIN).
Q_IMPORT_PLUGIN(SimulatorPlugin)

namespace tt::devices {

void registerBuiltInSimulator() {
    // Referencing this function links this file, whose Q_IMPORT_PLUGIN registers the plugin at start-up.
}

}  // namespace tt::devices
