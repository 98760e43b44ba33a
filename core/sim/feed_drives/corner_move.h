#pragma once

#include "core/sim/feed_drives/feed_drives_config.h"

namespace tt::core {

/// Slowest and fastest motor speed of a move the corrective pulse is designed for, rad/s (paper 002:
/// "the motor shaft speeds ranged from 0.5 to 9 rad/s").
inline constexpr double kMinCornerSpeedRadPerS = 0.5;
inline constexpr double kMaxCornerSpeedRadPerS = 9.0;

/// A corner between two linear moves (paper 002, Fig. 2): the motor speeds of X and Z on the first move
/// (before the velocity change) and on the second, rad/s. Both axes keep their direction (the moves go
/// from (x0, z0) through (x1, z1) to (x2, z2) with x and z increasing), so the speeds are magnitudes.
struct CornerMove {
    double x1RadPerS = 1.0;
    double z1RadPerS = 1.0;
    double x2RadPerS = 1.0;
    double z2RadPerS = 1.0;
};

/// Throws std::invalid_argument when a speed is outside 0.5 .. 9 rad/s, naming it ("Vz2 12 rad/s ...").
void validateCornerMove(const CornerMove& move);

/// A point of the X–Z plane, mm.
struct PlanePointMm {
    double xMm = 0.0;
    double zMm = 0.0;
};

/// The programmed path of a corner: the interpolator moves at (vx1, vz1) mm/s until t = 0, where it is
/// at the corner (x1, z1) = (0, 0), then at (vx2, vz2).
class CornerPath {
public:
    /// The path of `move` on the drives' screws.
    CornerPath(const FeedDrivesConfig& drives, const CornerMove& move);

    /// Programmed position at time `timeS` (0 = the velocity change), mm.
    PlanePointMm at(double timeS) const;
    /// Contour error: distance from `point` to the programmed path (the first move's line up to the
    /// corner, the second's from it), mm.
    double distanceMm(const PlanePointMm& point) const;
    /// Slide speeds of the first and second move, mm/s.
    PlanePointMm velocity1MmPerS() const { return m_v1; }
    PlanePointMm velocity2MmPerS() const { return m_v2; }

private:
    PlanePointMm m_v1;
    PlanePointMm m_v2;
};

}  // namespace tt::core
