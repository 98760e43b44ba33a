#pragma once

namespace tt::core {

/// The forced oscillation of the stopped cross feed (paper 001, way 1): amplitude 0.005..0.05 mm,
/// period 0.2..2 s, each stroke with acceleration, constant-velocity and deceleration phases.
struct DitherConfig {
    double amplitudeMm = 0.01;              ///< A: the motor command swings between −A and +A, mm
    double periodS = 1.0;                   ///< T: one forward and one reverse stroke, s
    double constantVelocityFraction = 0.6;  ///< share of each stroke spent at constant velocity
};

/// Motor command of the dither at one instant.
struct DitherState {
    double positionMm = 0.0;
    double velocityMmPerS = 0.0;
    double accelerationMmPerS2 = 0.0;
};

/// Trapezoidal-velocity dither: from rest at 0 a first stroke of length A to −A, then strokes of
/// 2A alternating forward and reverse, each of duration T/2 with equal acceleration and
/// deceleration times around a constant-velocity phase.
class DitherProfile {
public:
    /// Throws std::invalid_argument when amplitude, period or fraction are outside
    /// 0.005..0.05 mm, 0.2..2 s and 0.2..0.9.
    explicit DitherProfile(const DitherConfig& config);

    /// The command at `timeS` after the dither started (0 before it).
    DitherState at(double timeS) const;
    /// Speed of the constant-velocity phase, mm/s.
    double plateauSpeedMmPerS() const { return m_speed; }
    /// Duration of the constant-velocity phase of a full stroke, s.
    double plateauDurationS() const;
    const DitherConfig& config() const { return m_config; }

private:
    DitherState stroke(double t, double startMm, double direction, double lengthMm) const;

    DitherConfig m_config;
    double m_speed = 0.0;
    double m_accel = 0.0;
    double m_firstStrokeS = 0.0;
};

}  // namespace tt::core
