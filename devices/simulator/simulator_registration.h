#pragma once

namespace tt::devices {

/// Links the built-in simulator into the program as a static device plugin, so that DeviceManager finds it
/// among QPluginLoader::staticInstances() like any other plugin. Call it (any number of times) before a
/// DeviceManager lists its plugins; the program that does not call it has no simulator.
void registerBuiltInSimulator();

}  // namespace tt::devices
