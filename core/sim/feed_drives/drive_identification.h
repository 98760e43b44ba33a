#pragma once

#include <vector>

#include "core/sim/feed_drives/corner_simulation.h"
#include "core/sim/feed_drives/drive_drift.h"

namespace tt::core {

/// A corner as the controller recorded it on the machine: the move, the pulse it applied and the
/// encoder positions over time (CornerTrace::encoderXMm / encoderZMm, sampled as the simulator's trace).
struct RecordedCorner {
    CornerMove move;
    double amplitudeV = 0.0;
    CornerTrace trace;
};

/// The brackets of the identification, factors relative to the nominal drives.
struct DriveIdentificationSettings {
    double frictionMin = 0.25;
    double frictionMax = 4.0;  ///< lowered per drive to keep its static friction below 90 % of its peak torque
    double inertiaMin = 0.25;
    double inertiaMax = 4.0;
    double gainMin = 0.25;
    double gainMax = 4.0;
    int sweeps = 2;  ///< passes over the three factors of each drive
};

/// Throws std::invalid_argument when a bracket is outside 0.05 .. 1 (lower end) and 1 .. 20 (upper
/// end) or the sweeps outside 1 .. 5.
void validateDriveIdentification(const DriveIdentificationSettings& settings);

/// The drives' factors that make the controller's model reproduce the recorded corners.
struct DriveEstimate {
    FeedDrivesFactors factors;
    double xRmsUm = 0.0;    ///< RMS difference of the X encoder positions left, µm
    double zRmsUm = 0.0;    ///< the same for Z
    int missesLeftOut = 0;  ///< corners the fitted drives could not reproduce (a load hit them), left out
    int simulations = 0;    ///< corners simulated
};

/// RMS difference between the recorded encoder positions of `axis` and those simulated on `drives`
/// with each corner's pulse, µm. A corner the drives cannot run (a drive stalls) counts as 1 m off.
double encoderMismatchUm(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const PulseSettings& pulse,
                         const std::vector<RecordedCorner>& corners, FeedAxis axis, int traceEvery);

/// Re-identifies both drives from recorded corners: for each drive the factors of its velocity gain,
/// inertia and friction on `nominal` (the commissioned drives, not the model of the moment, so
/// successive identifications never compound) that minimise the mean over the corners of each corner's
/// RMS difference between the recorded and the simulated encoder positions of that drive (so that one
/// corner a load hit pulls less than on a least-squares fit). Coordinate descent from `start`: each
/// factor in turn (Z's before X's: the pulse fires on the Z encoder, so the X record depends on the Z
/// drive) by Brent's method on its logarithm within its bracket, `sweeps` times. Frictions that would
/// keep a drive from breaking away are never tried. A corner whose RMS difference is then more than
/// three times the median and above 2 µm is a miss (a load hit it): the descent is repeated without
/// the misses (when three corners are left). Throws
/// std::invalid_argument when no corner is given or a setting is out of range.
DriveEstimate identifyDrives(const FeedDrivesConfig& nominal, const FeedDrivesFactors& start,
                             const CornerCostSettings& cost, const PulseSettings& pulse,
                             const std::vector<RecordedCorner>& corners, const DriveIdentificationSettings& settings,
                             int traceEvery);

}  // namespace tt::core
