#pragma once

#include <optional>
#include <vector>

#include "core/calibration/probe_linearisation.h"
#include "core/storage/calibration_store.h"

namespace tt::ui {

/// One captured calibration point of the wizard.
struct CapturedPoint {
    double referenceUm = 0.0;  ///< reference deflection read on the dial indicator or micrometer, µm
    double adcCode = 0.0;      ///< mean ADC code
    int samples = 0;           ///< live samples averaged (0: typed)
};

/// Everything the probe linearisation wizard has gathered. It belongs to the Calibration page,
/// not to the wizard, so Back, Cancel and leaving the page never lose captured points.
struct ProbeCalibrationSession {
    int probeIndex = 0;
    int plane = 0;  ///< 0 = X (radial), 1 = Y
    int adcBits = 12;
    int referenceKind = 0;  ///< 0 = dial indicator, 1 = micrometer
    double resolutionUm = 1.0;
    std::vector<CapturedPoint> points;
    int degree = core::kAutoDegree;
    bool accepted = false;
    std::optional<storage::ProbeTableRecord> saved;
    bool uploadVerified = false;

    /// The points as the linearisation takes them.
    std::vector<core::CalibrationPoint> calibrationPoints() const {
        std::vector<core::CalibrationPoint> out;
        for (const CapturedPoint& p : points)
            out.push_back({p.referenceUm, p.adcCode, 0});
        return out;
    }
    /// Forgets everything (a new calibration).
    void clear() { *this = ProbeCalibrationSession{}; }
};

}  // namespace tt::ui
