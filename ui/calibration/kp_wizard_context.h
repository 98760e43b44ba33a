#pragma once

#include <QString>
#include <vector>

#include "ui/app_context.h"
#include "ui/calibration/device_kp_drive.h"
#include "ui/calibration/kp_session.h"

namespace tt::storage {
class CalibrationStore;
class ToolStore;
}  // namespace tt::storage

namespace tt::ui {

/// What the pages of the k_p wizard share.
struct KpWizardContext {
    AppContext* app = nullptr;
    KpSession* session = nullptr;
    std::vector<DeviceKpDrive*> drives;
    storage::CalibrationStore* calibrations = nullptr;
    storage::ToolStore* tools = nullptr;
    DeviceKpDrive* drive() const;
    core::KpCalibrationProcedure& procedure() const { return session->procedure; }
    QString operatorName() const;
};

}  // namespace tt::ui
