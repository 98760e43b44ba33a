#pragma once

#include "core/sim/feed_drives/feed_drive_axis.h"

namespace tt::core {

/// Which feed drive: X (cross slide) or Z (carriage).
enum class FeedAxis { X, Z };

/// "x" / "z".
const char* toString(FeedAxis axis);
/// Parses "x" / "z" (either case); throws std::invalid_argument otherwise.
FeedAxis feedAxisFromString(const char* text);

/// The carriage drive of the 1v340-feed-drives preset: five times the cross slide's inertia (paper 002:
/// X has less inertia than Z), more friction, a stiffer velocity loop.
FeedDriveAxisConfig defaultZDrive();

/// The two feed drives of the lathe and the integration step of their simulation.
struct FeedDrivesConfig {
    FeedDriveAxisConfig x;                    ///< cross slide (less inertia, paper 002)
    FeedDriveAxisConfig z = defaultZDrive();  ///< carriage
    double stepS = 1e-4;                      ///< integration step, s (at most 0.1 ms)
};

/// Largest integration step, s (issue 15: ≤ 0.1 ms).
inline constexpr double kMaxFeedDriveStepS = 1e-4;

/// Throws std::invalid_argument naming the axis and the value out of range.
void validateFeedDrives(const FeedDrivesConfig& config);

/// The drive of `axis`.
const FeedDriveAxisConfig& axisConfig(const FeedDrivesConfig& config, FeedAxis axis);
/// The drive of `axis`, to change it.
FeedDriveAxisConfig& axisConfig(FeedDrivesConfig& config, FeedAxis axis);

/// Multiplies the viscous, Coulomb and static friction of `axis` by `factor` (drift of the ways).
void scaleFriction(FeedDrivesConfig& config, FeedAxis axis, double factor);

}  // namespace tt::core
