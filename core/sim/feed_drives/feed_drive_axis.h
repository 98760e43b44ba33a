#pragma once

namespace tt::core {

/// One feed drive of a CNC lathe (paper 002, 1V340F30): a DC servo motor turning a ball screw that
/// moves the slide. The CNC closes the position loop (P gain Kv on the encoder's quantised position,
/// analog velocity command in volts); the drive closes a PI velocity loop on the tachogenerator with a
/// current limit; the motor carries the rotor, screw and reflected slide inertia against viscous,
/// Coulomb and breakaway (static) friction. The screw is taken rigid (its first mode is far above the
/// loops' bandwidth). Friction while moving is T(ω) = sign(ω)·(Tc + (Ts − Tc)·exp(−(ω/ωs)²)) + b·ω
/// (Coulomb, static and viscous with the Stribeck fall at low speed; Armstrong-Hélouvry, Dupont and
/// Canudas de Wit, Automatica 30(7), 1994). Units: rad, s, N·m, A, V; slide positions in mm.
struct FeedDriveAxisConfig {
    double inertiaKgM2 = 0.004;              ///< motor + screw + slide reflected to the motor shaft, kg·m²
    double torqueConstantNmPerA = 1.0;       ///< motor torque per armature current, N·m/A
    double currentLimitA = 20.0;             ///< the drive's current limit, A
    double viscousFrictionNmSPerRad = 0.02;  ///< N·m per rad/s
    double coulombFrictionNm = 0.5;          ///< sliding friction of ways and screw, N·m
    double staticFrictionNm = 1.2;           ///< breakaway friction (≥ Coulomb), N·m
    double stribeckSpeedRadPerS = 2.0;       ///< speed over which friction falls from static to Coulomb, rad/s
    double screwLeadMm = 10.0;               ///< slide travel per motor revolution, mm
    double encoderStepMm = 0.001;            ///< position quantum of the encoder, mm
    double positionGainPerS = 16.7;          ///< CNC position loop gain Kv: slide mm/s per mm of following error
    double speedPerVoltRadPerSPerV = 20.0;   ///< motor speed per volt of velocity command, rad/s/V
    double commandLimitV = 10.0;             ///< the CNC's analog output range, ±V
    double velocityGainAPerRadPerS = 0.6;    ///< proportional gain of the velocity loop, A per rad/s
    double velocityIntegralTimeS = 0.015;    ///< integral time of the velocity loop, s (0: P only)
    /// The drive's real motor speed per volt of velocity command over speedPerVolt, the value the CNC was
    /// commissioned with and scales its output by (1: as commissioned). A drifting tachogenerator or input
    /// scaling changes it: the same volts then make another speed, which changes the position loop's
    /// effective gain and what the corrective pulse does.
    double velocityGainFactor = 1.0;
};

/// Throws std::invalid_argument naming the first value outside its physical range ("Z: screw lead
/// 0 mm is outside 0.1 .. 100"), or when the Coulomb or the static friction is not below the torque at
/// the current limit (the motor could never move, or never break away); `axis` prefixes the message.
void validateFeedDriveAxis(const FeedDriveAxisConfig& config, const char* axis);

/// Motor speed in rad/s for a slide speed in mm/s (ω = 2π v / lead).
double motorSpeedRadPerS(const FeedDriveAxisConfig& config, double slideMmPerS);
/// Slide speed in mm/s for a motor speed in rad/s (v = ω lead / 2π).
double slideSpeedMmPerS(const FeedDriveAxisConfig& config, double motorRadPerS);

/// The simulated drive of one axis, stepped by explicit (symplectic) Euler. Friction is Karnopp's
/// model: a motor at rest stays at rest while the driving torque is below breakaway.
class FeedDriveAxis {
public:
    /// A drive at rest at slide position `positionMm`; validates the configuration.
    FeedDriveAxis(const FeedDriveAxisConfig& config, double positionMm);

    /// Puts the drive in the steady state of following a ramp at `slideMmPerS` with the programmed
    /// position `commandMm` at this instant: motor at speed, following error Kv⁻¹ v (plus the droop of
    /// a P-only velocity loop), integrator holding the friction torque.
    void settleOnRamp(double commandMm, double slideMmPerS);

    /// Advances by `dtS` with the CNC's programmed position `commandMm`, an extra velocity command
    /// `extraV` (the corrective pulse, volts, added to the CNC's output) and a load torque on the motor.
    void step(double dtS, double commandMm, double extraV = 0.0, double loadTorqueNm = 0.0);

    /// True slide position, mm.
    double positionMm() const;
    /// What the encoder reports: the slide position rounded down to a whole number of steps, mm.
    double encoderMm() const;
    /// Motor speed, rad/s.
    double speedRadPerS() const { return m_speed; }
    /// Armature current after the limit, A.
    double currentA() const { return m_current; }
    /// Velocity command the drive received, V (CNC output + extra, within the output range).
    double commandV() const { return m_commandV; }
    /// The parameters.
    const FeedDriveAxisConfig& config() const { return m_config; }

private:
    double frictionTorqueNm(double direction) const;

    FeedDriveAxisConfig m_config;
    double m_angleRad = 0.0;
    double m_speed = 0.0;
    double m_integralRadPerS = 0.0;  ///< ∫ speed error dt / Ti, rad/s
    double m_current = 0.0;
    double m_commandV = 0.0;
    bool m_stuck = true;
};

}  // namespace tt::core
