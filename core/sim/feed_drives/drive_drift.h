#pragma once

#include <string>

#include "core/sim/feed_drives/feed_drives_config.h"

namespace tt::core {

/// What drifts in a feed drive while the machine works (paper 002: "the parameters of the drive systems
/// change with time", which is what the network is retrained for).
enum class DriveDriftKind {
    Friction,  ///< viscous, Coulomb and static friction of the ways and the screw
    Gain,      ///< the drive's velocity gain: motor speed per volt of velocity command (tachogenerator, scaling)
    Inertia,   ///< the inertia at the motor shaft: the slide and what it carries
};

/// "friction", "gain", "inertia".
const char* toString(DriveDriftKind kind);
/// Parses the names toString gives; throws std::invalid_argument naming the text and the choices.
DriveDriftKind driveDriftKindFromString(const std::string& text);

/// The drift factors a work run accepts, for every kind.
inline constexpr double kMinDriveDriftFactor = 0.5;
inline constexpr double kMaxDriveDriftFactor = 3.0;

/// One drive's friction, inertia and velocity gain relative to the nominal drive (1: nominal).
struct DriveFactors {
    double friction = 1.0;      ///< multiplies the viscous, Coulomb and static friction
    double inertia = 1.0;       ///< multiplies the inertia at the motor
    double velocityGain = 1.0;  ///< multiplies the speed per volt the drive really makes (velocityGainFactor)
};

/// Both drives' factors: the drift of a machine, or what the controller identified.
struct FeedDrivesFactors {
    DriveFactors x;
    DriveFactors z;
};

/// The factors of `axis`.
const DriveFactors& axisFactors(const FeedDrivesFactors& factors, FeedAxis axis);
/// The factors of `axis`, to change them.
DriveFactors& axisFactors(FeedDrivesFactors& factors, FeedAxis axis);

/// `nominal` with `factors` applied. Throws std::invalid_argument when a factor is not above 0 or the
/// result is not a valid drive (validateFeedDrives: e.g. "Z: static friction 30 N·m is not below the
/// torque at the current limit (24 N·m): the motor could never break away").
FeedDrivesConfig scaledDrives(const FeedDrivesConfig& nominal, const FeedDrivesFactors& factors);

/// The factors of a drift of `kind` by `factor` on `axis`, all others 1. Throws std::invalid_argument
/// when `factor` is outside 0.5 .. 3.
FeedDrivesFactors driftFactors(DriveDriftKind kind, FeedAxis axis, double factor);

/// "X friction x1.000, inertia x1.000, gain x1.000; Z ..." with `decimals` decimals.
std::string describeFactors(const FeedDrivesFactors& factors, int decimals);

}  // namespace tt::core
