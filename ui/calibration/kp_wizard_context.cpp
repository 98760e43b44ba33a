#include "ui/calibration/kp_wizard_context.h"

#include <algorithm>

#include "ui/app_state.h"

namespace tt::ui {

DeviceKpDrive* KpWizardContext::drive() const {
    if (drives.empty()) return nullptr;
    return drives[static_cast<std::size_t>(std::clamp(session->driveIndex, 0, static_cast<int>(drives.size()) - 1))];
}

QString KpWizardContext::operatorName() const {
    return app && app->state ? app->state->operatorName().trimmed() : QString();
}

}  // namespace tt::ui
