#pragma once

#include <QString>

namespace tt::devices {

/// Folder of the device plugins relative to the executable: <exe>/../lib/trueturn/plugins
/// (bin/trueturn -> lib/trueturn/plugins when installed; build/app/trueturn ->
/// build/lib/trueturn/plugins in the build tree). TRUETURN_PLUGIN_DIR overrides it.
/// Never an absolute path compiled in. Needs a QCoreApplication.
QString defaultPluginFolder();

/// The folder relative to the executable folder, for the install rule and the build tree.
inline constexpr const char* kPluginSubfolder = "../lib/trueturn/plugins";

}  // namespace tt::devices
