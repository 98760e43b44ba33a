#pragma once

#include <string>
#include <vector>

#include "core/loop/loop_config.h"
#include "devices/parsers/parametric_gcode.h"

namespace tt::devices::linuxcnc {

/// The machine and shop conventions of TrueTurn's LinuxCNC part program besides the loop's own numbers.
struct ProgramOptions {
    /// The first correction parameter (#first ..); 0: no parameters, the nominal path with the wear applied by
    /// G43.2 H<wearTool> (wear mode).
    int firstParameter = 500;
    ProgramConventions conventions;
    double feed = 0.25;  ///< mm/rev (G95), or mm/min with feedPerMinute (G94)
    bool feedPerMinute = false;
    int spindleRpm = 546;
    int toolNumber = 1;
    int wearTool = 10001;  ///< wear mode only
    double zOriginMm = 0.0;
    int zDirection = -1;
    double clearanceMm = 2.0;
    double largestTotalMm = 0.5;  ///< the program refuses to cut with a correction beyond this, radial mm
    int programNumber = 1001;
    std::vector<std::string> notes;
};

/// The part program job of a run: the loop's control points, its interpolation (PCHIP computed in the program;
/// the natural spline as fixed slope weights), the approximation unit's path grid (core::buildCorrectionPath,
/// the same samples the CNC gets from a G-code file output) with its feed-forward and the nominal diameter. Throws
/// std::invalid_argument on a bad loop configuration.
ParametricProgramJob programJob(const core::LoopConfig& loop, const ProgramOptions& options);

}  // namespace tt::devices::linuxcnc
