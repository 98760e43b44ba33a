#include "core/sim/feed_drives/drive_drift.h"

#include <cmath>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

void applyFactors(FeedDriveAxisConfig& c, const DriveFactors& f, const char* axis) {
    for (double v : {f.friction, f.inertia, f.velocityGain})
        if (!std::isfinite(v) || v <= 0.0)
            throw std::invalid_argument(std::string(axis) + ": a drive factor " + formatSignificant(v, 6) +
                                        " is not above 0");
    c.viscousFrictionNmSPerRad *= f.friction;
    c.coulombFrictionNm *= f.friction;
    c.staticFrictionNm *= f.friction;
    c.inertiaKgM2 *= f.inertia;
    c.velocityGainFactor *= f.velocityGain;
}

std::string describeAxis(const char* axis, const DriveFactors& f, int decimals) {
    return std::string(axis) + " friction x" + formatFixed(f.friction, decimals) + ", inertia x" +
           formatFixed(f.inertia, decimals) + ", gain x" + formatFixed(f.velocityGain, decimals);
}

}  // namespace

const char* toString(DriveDriftKind kind) {
    switch (kind) {
        case DriveDriftKind::Friction:
            return "friction";
        case DriveDriftKind::Gain:
            return "gain";
        case DriveDriftKind::Inertia:
            return "inertia";
    }
    return "friction";
}

DriveDriftKind driveDriftKindFromString(const std::string& text) {
    for (DriveDriftKind k : {DriveDriftKind::Friction, DriveDriftKind::Gain, DriveDriftKind::Inertia})
        if (text == toString(k)) return k;
    throw std::invalid_argument("drift kind '" + text + "' is none of friction, gain, inertia");
}

const DriveFactors& axisFactors(const FeedDrivesFactors& factors, FeedAxis axis) {
    return axis == FeedAxis::X ? factors.x : factors.z;
}

DriveFactors& axisFactors(FeedDrivesFactors& factors, FeedAxis axis) {
    return axis == FeedAxis::X ? factors.x : factors.z;
}

FeedDrivesConfig scaledDrives(const FeedDrivesConfig& nominal, const FeedDrivesFactors& factors) {
    FeedDrivesConfig d = nominal;
    applyFactors(d.x, factors.x, "X");
    applyFactors(d.z, factors.z, "Z");
    validateFeedDrives(d);
    return d;
}

FeedDrivesFactors driftFactors(DriveDriftKind kind, FeedAxis axis, double factor) {
    if (!std::isfinite(factor) || factor < kMinDriveDriftFactor || factor > kMaxDriveDriftFactor)
        throw std::invalid_argument("drift factor " + formatSignificant(factor, 6) + " is outside " +
                                    formatSignificant(kMinDriveDriftFactor, 3) + " .. " +
                                    formatSignificant(kMaxDriveDriftFactor, 3));
    FeedDrivesFactors f;
    DriveFactors& a = axisFactors(f, axis);
    switch (kind) {
        case DriveDriftKind::Friction:
            a.friction = factor;
            break;
        case DriveDriftKind::Gain:
            a.velocityGain = factor;
            break;
        case DriveDriftKind::Inertia:
            a.inertia = factor;
            break;
    }
    return f;
}

std::string describeFactors(const FeedDrivesFactors& factors, int decimals) {
    return describeAxis("X", factors.x, decimals) + "; " + describeAxis("Z", factors.z, decimals);
}

}  // namespace tt::core
