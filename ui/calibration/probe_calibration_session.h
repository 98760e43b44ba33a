#pragma once

#include <optional>

#include "core/calibration/probe_procedure.h"
#include "core/storage/calibration_store.h"

namespace tt::ui {

/// Everything the probe linearisation wizard has gathered: the procedure (its set-up, points,
/// fit, checks and upload) and what the wizard keeps besides. It belongs to the Calibration page,
/// not to the wizard, so Back, Cancel and leaving the page never lose captured points.
struct ProbeCalibrationSession {
    int probeIndex = 0;
    int referenceKind = 0;  ///< 0 = dial indicator, 1 = micrometer
    core::ProbeLinearisationProcedure procedure{core::ProbeProcedureConfig{}};
    std::optional<storage::ProbeTableRecord> saved;

    /// Forgets everything (a new calibration).
    void clear() { *this = ProbeCalibrationSession{}; }
};

}  // namespace tt::ui
