#pragma once

namespace tt::core {

// The blocks of the feed stabiliser's chain (paper 003), each as the equation the paper gives.
// They are the pieces of the ODE's right-hand side (HydraulicFeedModel::derivative) and are tested
// one by one against their analytic step responses.

/// Electromagnet, eq. 1 (L di/dt + r i = U): di/dt in A/s.
double magnetCurrentRate(double currentA, double voltageV, double inductanceH, double resistanceOhm);

/// Armature force, eq. 6 (F_e = K_e i^2), N.
double armatureForce(double currentA, double gainNPerA2);

/// The spool as a second-order link, eq. 9 (T_z^2 h'' + 2 xi T_z h' + h = K_z F_e): h'' in m/s^2.
double spoolAcceleration(double positionM, double velocityMPerS, double forceN, double timeConstantS,
                         double dampingRatio, double gainMPerN);

/// The slot's opening m from the spool position h: shut while the spool is within its lap
/// (overlapM), open by h - lap beyond it, and no more than the full opening, m.
double slotOpening(double spoolPositionM, double overlapM, double maxOpeningM);

/// Slot flow, eq. 15 (Q = k_s m; linear because the reducing valve holds the pressure drop), m^3/s.
double slotFlow(double openingM, double slotGainM2PerS);

/// Leakage of the cylinder under the load R at steady motion, alpha_0 = k_y R / F (eq. 20, as a
/// flow: the paper's 1.268e-5 m^3/s), m^3/s.
double leakageFlow(double loadN, double leakagePerNewtonM3PerS);

/// The cylinder, eq. 21 with eq. 20's coefficients (T_c v' + v = k_0 (Q - alpha_0)): v' in m/s^2.
double cylinderAcceleration(double feedMPerS, double flowM3PerS, double leakageM3PerS, double timeConstantS,
                            double gainPerM2);

/// The radial cutting force the sensor reads: the load at the set feed scaled by the chip thickness,
/// P_y = P (v / S)^y (zero while the carriage stands or backs off), N.
double sensedForce(double loadN, double feedMPerS, double setFeedMPerS, double feedExponent);

}  // namespace tt::core
