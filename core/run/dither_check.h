#pragma once

#include <optional>
#include <string>

#include "core/sim/boring/boring_machine.h"

namespace tt::core {

/// Why a dither cannot serve the force-from-current estimate (paper 001, way 1), decided before the run.
enum class DitherProblem {
    None,
    TooSmallToResolve,      ///< the slide's travel per stroke, after the screw's wind-up, is too short to see
    SlowerThanOffset,       ///< the dither is not at least twice as fast as the offset may move
    RippleBeyondTolerance,  ///< the dither's own ripple on the diameter exceeds the bore tolerance
};

/// The verdict on a dither with the value that would pass (for the same period).
struct DitherVerdict {
    DitherProblem problem = DitherProblem::None;
    std::string reason;                      ///< the user's terms: what, the value, the limit
    std::optional<double> validAmplitudeMm;  ///< smallest (largest for the ripple) amplitude that passes
    std::optional<double> validPeriodS;      ///< or the period that passes with the same amplitude
    double plateauSpeedMmPerS = 0.0;         ///< V = 8 A / (T (1 + f)) of the trapezoid
    double slideTravelMm = 0.0;              ///< 2 A minus the wind-up 2 F_static / k_screw
    double cyclesAtSpeed = 0.0;              ///< PLC cycles the slide moves per stroke
    /// No problem.
    bool ok() const { return problem == DitherProblem::None; }
};

/// Factor by which the dither's plateau speed must exceed the offset's rate limit: with the offset
/// moving at its full rate r the slide's absolute stroke speeds are V + r and V - r, and V >= 2 r keeps
/// the slower at least half the dither speed (slower strokes stick and slip on the guideways).
inline constexpr double kDitherOverOffsetRate = 2.0;

/// Checks that the scenario's dither can be resolved by the estimator on its drive at its PLC cycle:
/// (1) the slide travel per stroke 2 A - 2 F_static / k_screw lasts at least `minPlateauSamples` PLC
/// cycles at the plateau speed and is at least the estimator's minimum stroke; (2) the plateau speed is
/// at least kDitherOverOffsetRate times the offset rate limit; (3) the ripple 2 A on the diameter is
/// within the bore tolerance when the scenario gives one. The first problem found is returned.
DitherVerdict checkDither(const BoringScenario& scenario);

/// Throws std::invalid_argument with the verdict's reason unless checkDither passes.
void requireResolvableDither(const BoringScenario& scenario);

}  // namespace tt::core
