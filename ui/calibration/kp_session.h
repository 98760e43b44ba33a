#pragma once

#include <QStringList>
#include <memory>

#include "core/calibration/kp_procedure.h"
#include "core/control/dither_current_difference.h"

namespace tt::ui {

/// What the k_p wizard has gathered: the procedure (loads, fit, checks) and what the wizard keeps
/// besides; owned by the Calibration page (Back/Cancel keep it).
struct KpSession {
    int driveIndex = 0;
    QStringList toolIds;  ///< tools that receive the new k_p
    core::KpCalibrationProcedure procedure{std::make_unique<core::DitherCurrentDifference>()};
    bool saved = false;
    void clear() { *this = KpSession{}; }
};

}  // namespace tt::ui
