#pragma once

#include <random>

#include "core/ports/drive_current.h"

namespace tt::core {

/// The cross-feed drive of a heavy lathe (paper 001, way 1): the motor follows its position
/// command through a compliant, damped transmission (ball screw, nut, bearings) to the cross
/// slide, which carries the boring bar and slides on guideways with static, Coulomb and viscous
/// friction. The motor current is the transmitted force plus the motor-side inertia force over
/// k_p, plus noise: I = (F_transmission + m_motor a_motor) / k_p + noise.
/// Units: mm, s, N, kg. X positive away from the spindle axis.
struct CrossFeedDriveConfig {
    double slideMassKg = 800.0;                  ///< cross slide, tool post and bar, kg
    double motorInertiaKg = 60.0;                ///< rotor and screw inertia reflected to the slide, kg
    double coulombFrictionN = 975.0;             ///< guideway sliding friction, N
    double staticFrictionN = 1070.0;             ///< breakaway friction (≥ Coulomb), N
    double viscousFrictionNsPerMm = 50.0;        ///< N per mm/s
    double transmissionStiffnessNPerMm = 5.0e5;  ///< motor-to-slide stiffness, N/mm
    double transmissionDampingNsPerMm = 300.0;   ///< N per mm/s
    double currentToForceNPerA = 150.0;          ///< the drive's true k_p, N/A
    double currentNoiseA = 0.3;                  ///< RMS noise of a current sample, A
    double velocityNoiseMmPerS = 0.0005;         ///< RMS noise of a slide velocity sample, mm/s
    double positionNoiseMm = 0.0001;             ///< RMS noise of a linear-scale reading, mm
};

/// The motor's position command at one instant (the dither plus the offset and any feed motion).
struct MotorCommand {
    double positionMm = 0.0;
    double velocityMmPerS = 0.0;
    double accelerationMmPerS2 = 0.0;
};

/// Simulated cross-feed drive; deterministic for a given seed.
class CrossFeedDrive {
public:
    /// Throws std::invalid_argument for non-physical parameters (negative friction, static below
    /// Coulomb, non-positive mass, stiffness or k_p).
    CrossFeedDrive(const CrossFeedDriveConfig& config, unsigned long long seed);

    /// Advances by dtS with the motor at `command` and an external force on the slide along X
    /// (the cutting force through the bar: −P when P pushes the tool towards the axis).
    void step(double dtS, const MotorCommand& command, double externalForceN);

    /// Slide position, mm (radial, towards the axis positive).
    double slidePositionMm() const { return m_slideMm; }
    /// Slide velocity, mm/s.
    double slideVelocityMmPerS() const { return m_slideVelocity; }
    /// Force the motor produces, N (transmission force + motor-side inertia).
    double motorForceN() const { return m_motorForceN; }
    /// True motor current without noise, A.
    double currentA() const { return m_motorForceN / m_config.currentToForceNPerA; }
    /// A sample as the drive reports it: current, slide velocity and position with noise.
    DriveSample sample(double timeS);
    /// The drive's parameters.
    const CrossFeedDriveConfig& config() const { return m_config; }

private:
    CrossFeedDriveConfig m_config;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    double m_slideMm = 0.0;
    double m_slideVelocity = 0.0;
    double m_motorForceN = 0.0;
    bool m_stuck = true;
};

}  // namespace tt::core
