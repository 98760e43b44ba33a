#pragma once

#include <QString>

#include "core/storage/plant_forwarder.h"

namespace tt::ui {

/// The plant database's link in the operator's words and language, for the Run page and the status bar:
/// "Plant database offline since 14:02, 37 parts kept on this terminal", "Plant database: every part sent".
QString plantLinkText(const storage::ForwarderStatus& status);

/// Whether the link needs the operator's eye (offline, or the journal nearly full).
bool plantLinkWarns(const storage::ForwarderStatus& status);

}  // namespace tt::ui
