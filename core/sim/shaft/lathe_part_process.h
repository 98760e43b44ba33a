#pragma once

#include <cstdint>
#include <vector>

#include "core/ports/correction_output.h"

namespace tt::core {

/// A finished part as it leaves the machine: its diameter along the axis.
struct TurnedPart {
    std::int64_t partNumber = 0;
    std::vector<double> zMm;         ///< positions along the part, mm, increasing
    std::vector<double> diameterMm;  ///< true diameter there, mm

    /// Diameter at z by linear interpolation, the end values outside the grid, mm.
    double diameterAtMm(double zMm) const;
};

/// Something that machines parts for the simulated station: the physical lathe simulator
/// (LatheSimulator) or the statistical plant of the controller's design model
/// (LatheStatisticalProcess). Deterministic for its seed: machining the same part number with the
/// same correction gives the same part, whatever was machined before.
class LathePartProcess {
public:
    virtual ~LathePartProcess() = default;

    /// Machines part `correction.partNumber` (>= 1) with the corrections the CNC received.
    virtual TurnedPart machine(const PartCorrection& correction) = 0;
    /// Nominal diameter of the part, mm.
    virtual double nominalDiameterMm() const = 0;
    /// Length of the part, mm.
    virtual double partLengthMm() const = 0;
};

}  // namespace tt::core
