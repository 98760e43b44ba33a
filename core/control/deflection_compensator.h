#pragma once

#include <optional>

namespace tt::core {

/// Limits of the dynamic X offset written to the CNC (in-process compensation).
struct CompensatorLimits {
    double maxOffsetMm = 0.5;    ///< |offset| never exceeds this, mm
    double maxRateMmPerS = 0.2;  ///< the offset changes by at most this per second, mm/s
};

/// Outcome of one PLC cycle of the compensator.
struct CompensationStep {
    double targetMm = 0.0;  ///< the offset that would cancel the measured deflection, mm
    double offsetMm = 0.0;  ///< the offset to send, after the limits, mm
    bool rateLimited = false;
    bool rangeLimited = false;
    bool holding = false;  ///< no valid measurement this cycle: the last offset is kept (the caller knows why)
};

/// The in-process deflection compensator (paper 001: "correction on X = minus the deflection",
/// applied as a dynamic tool offset by the PLC every cycle of 10..100 ms). Each cycle it takes
/// the tool tip deflection along X (from the current or the probe source), aims at the offset
/// −deflection, and moves towards it within the rate and range limits. Without a valid
/// deflection it holds the last offset (the last safe correction).
class DeflectionCompensator {
public:
    /// Throws std::invalid_argument for non-positive limits.
    explicit DeflectionCompensator(const CompensatorLimits& limits);

    /// One cycle of `dtS` seconds; `deflectionMm` = tip deflection along X (negative: towards the
    /// axis), nullopt or non-finite = none valid (hold).
    CompensationStep step(double dtS, std::optional<double> deflectionMm);

    double offsetMm() const { return m_offsetMm; }
    const CompensatorLimits& limits() const { return m_limits; }
    /// Sets the offset to 0 (new tool or bore).
    void reset() { m_offsetMm = 0.0; }
    /// Takes back the offset the CNC really holds (after a failed write), clamped to the range.
    void restoreOffset(double offsetMm);

private:
    CompensatorLimits m_limits;
    double m_offsetMm = 0.0;
};

}  // namespace tt::core
