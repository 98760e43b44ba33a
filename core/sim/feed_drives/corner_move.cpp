#include "core/sim/feed_drives/corner_move.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

void requireSpeed(double v, const char* name) {
    if (!std::isfinite(v) || v < kMinCornerSpeedRadPerS || v > kMaxCornerSpeedRadPerS)
        throw std::invalid_argument(std::string(name) + " " + formatSignificant(v, 6) +
                                    " rad/s is outside the motor speeds the pulse is designed for, 0.5 .. 9 rad/s");
}

// Distance from p to the ray {t d : t >= 0} (d != 0).
double distanceToRay(const PlanePointMm& p, const PlanePointMm& d) {
    const double dd = d.xMm * d.xMm + d.zMm * d.zMm;
    const double t = std::max(0.0, (p.xMm * d.xMm + p.zMm * d.zMm) / dd);
    return std::hypot(p.xMm - t * d.xMm, p.zMm - t * d.zMm);
}

}  // namespace

void validateCornerMove(const CornerMove& m) {
    requireSpeed(m.x1RadPerS, "Vx1");
    requireSpeed(m.z1RadPerS, "Vz1");
    requireSpeed(m.x2RadPerS, "Vx2");
    requireSpeed(m.z2RadPerS, "Vz2");
}

CornerPath::CornerPath(const FeedDrivesConfig& drives, const CornerMove& move)
    : m_v1{slideSpeedMmPerS(drives.x, move.x1RadPerS), slideSpeedMmPerS(drives.z, move.z1RadPerS)},
      m_v2{slideSpeedMmPerS(drives.x, move.x2RadPerS), slideSpeedMmPerS(drives.z, move.z2RadPerS)} {
    validateCornerMove(move);
}

PlanePointMm CornerPath::at(double timeS) const {
    const PlanePointMm& v = timeS < 0.0 ? m_v1 : m_v2;
    return {v.xMm * timeS, v.zMm * timeS};
}

double CornerPath::distanceMm(const PlanePointMm& p) const {
    // The first move runs towards the corner: its ray from the corner points backwards.
    return std::min(distanceToRay(p, {-m_v1.xMm, -m_v1.zMm}), distanceToRay(p, m_v2));
}

}  // namespace tt::core
