#pragma once

#include <cstdint>
#include <string>

#include "core/ports/correction_output.h"

namespace tt::devices {

/// What the G-code of the corrected finishing pass needs besides the path: the part and the
/// machine conventions. Lathe, metric (G21), feed per revolution (G95), XZ plane (G18).
struct GCodeJob {
    double nominalDiameterMm = 27.0;  ///< finished diameter the correction is added to, mm
    double feedMmPerRev = 0.25;       ///< finishing feed, mm/rev (paper 000: 0.25)
    int spindleRpm = 546;             ///< constant spindle speed, rpm (0: leave the spindle alone)
    bool diameterMode = true;         ///< X words are diameters (else radii)
    bool emitModeCode = false;        ///< also write G7 (diameter) / G8 (radius), as LinuxCNC expects
    double zOriginMm = 0.0;           ///< machine Z of the part's x = 0 (its left end), mm
    int zDirection = -1;              ///< machine Z = zOriginMm + zDirection * x (+1 or -1)
    double clearanceMm = 2.0;         ///< radial and axial clearance of the approach and retract, mm
    int toolNumber = 1;               ///< T word (tool and offset number), 1..99
    int programNumber = 1001;         ///< O word, 1..9999
    double maxCorrectionMm = 0.5;     ///< largest radial correction accepted, mm (safety limit)
};

/// The G-code program of the corrected cutting path for the next part. The header states the
/// part, the units (G21, mm), the X mode (diameter or radius) and the sign convention; each G1
/// segment ends at one point of the path with its correction in a comment (the approximation
/// unit's correction per segment, paper 000: y_set(x) = y_ff(x) + y(x)). Coordinates with three
/// decimals (0.001 mm). Throws std::invalid_argument, in the user's terms, for an empty or
/// inconsistent path, non-finite values, a correction beyond maxCorrectionMm, or a bad job.
std::string writeCorrectionGCode(const core::PartCorrection& correction, const GCodeJob& job);

}  // namespace tt::devices
