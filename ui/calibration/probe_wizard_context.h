#pragma once

#include <QString>
#include <vector>

#include "ui/app_context.h"
#include "ui/calibration/device_calibration_probe.h"
#include "ui/calibration/probe_calibration_session.h"

namespace tt::storage {
class CalibrationStore;
}

namespace tt::ui {

/// What the pages of the probe wizard share: the session (its procedure holds the steps), the
/// probes offered and the store.
struct ProbeWizardContext {
    AppContext* app = nullptr;
    ProbeCalibrationSession* session = nullptr;
    std::vector<DeviceCalibrationProbe*> probes;
    storage::CalibrationStore* store = nullptr;

    DeviceCalibrationProbe* probe() const;
    core::ProbeLinearisationProcedure& procedure() const { return session->procedure; }
    QString operatorName() const;
    /// Forwards the probe's samples to the procedure (`elapsedS` of wall time since the last call).
    void pumpProbe(double elapsedS) const;
    /// Plane, ADC resolution and the instrument's division into the procedure (back to its capture step).
    void setUp(int plane, int adcBits, double divisionUm) const;
};

}  // namespace tt::ui
