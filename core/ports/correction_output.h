#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/ports/device_health.h"

namespace tt::core {

/// The corrected cutter path for one part: radial X correction as a function of the axial
/// coordinate z (paper 000: y_set(x) = y_ff(x) + y(x)). Both vectors have the same length.
struct CorrectionPath {
    std::vector<double> zMm;            ///< axial positions along the part, mm (increasing)
    std::vector<double> xCorrectionMm;  ///< radial cutter correction at zMm, mm (negative = towards the axis)
};

/// Everything the CNC needs for the next part.
struct PartCorrection {
    std::int64_t partNumber = 0;
    std::vector<double> pointZMm;           ///< control point positions, mm
    std::vector<double> pointCorrectionMm;  ///< per-point radial corrections actually applied, mm
    CorrectionPath path;                    ///< the smooth corrected path along the part
};

/// Outcome of a write to the CNC.
struct OutputResult {
    bool ok = false;
    std::string message;  ///< why it failed, in the user's terms; empty when ok
};

/// The correction output to the CNC: a per-part path (run-to-run) or a dynamic X tool
/// offset applied by the PLC every cycle (in-process boring compensation).
class CorrectionOutput {
public:
    virtual ~CorrectionOutput() = default;
    /// Whether the output can take corrections now, with the reason when not.
    virtual DeviceHealth health() const = 0;
    /// Sends the corrections for the next part.
    virtual OutputResult sendPartCorrection(const PartCorrection& correction) = 0;
    /// Sets the dynamic X offset, mm (radial), applied by the PLC from its next cycle.
    virtual OutputResult sendDynamicOffset(double xOffsetMm) = 0;
};

}  // namespace tt::core
