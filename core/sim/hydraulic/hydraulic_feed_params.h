#pragma once

#include <span>
#include <string>

namespace tt::core {

/// The hydraulic feed drive of a finishing lathe with its feed stabiliser (paper 003, Muslimov,
/// Almasbekov, Sarymsakov 2020): the carriage is moved by a cylinder on hydrostatic ways; an inductive
/// sensor reads the tool's elastic displacement under the radial cutting force; the amplified signal
/// drives an electromagnet whose armature opens a spool flow regulator to make up the cylinder's
/// leakage. SI units throughout. Defaults are the preset "hydraulic-feed" (its notes say which values
/// are printed in the paper and which are derived).
struct HydraulicFeedParams {
    // Cylinder and carriage (paper eqs. 18-22).
    double carriageMassKg = 81.0;      ///< M, moving mass of carriage and piston, kg
    double pistonDiameterM = 0.15;     ///< D, bore of the working chamber, m (area F = pi D^2 / 4)
    double leakageM3PerSPa = 6.94e-8;  ///< k_y, internal leakage per pascal of chamber pressure, m^3/(s Pa)
    double setFeedMPerS = 1.0e-3;      ///< S, the set feed (the pump delivers S F), m/s

    // The regulator's slot (eqs. 14-15): Q = k_s m with k_s = mu pi d1 sqrt(2 dp / rho).
    double dischargeCoefficient = 0.63;  ///< mu, 0.62..0.65 in the paper
    double plungerDiameterM = 0.004;     ///< d1, m
    double pressureDropPa = 1.0e5;       ///< dp across the slot, held by the pressure-reducing valve, Pa
    double oilDensityKgPerM3 = 900.0;    ///< rho, kg/m^3
    double maxOpeningM = 4.0e-4;         ///< the slot's full opening (the spool's stop), m

    // The spool (eqs. 7-13): T_z^2 h'' + 2 xi T_z h' + h = K_z F_e.
    double spoolTimeConstantS = 0.003;  ///< T_z = sqrt(M_z / c), s
    double spoolDampingRatio = 1.2;     ///< xi = theta / (2 c T_z)
    double spoolGainMPerN = 7.6e-5;     ///< K_z = 1 / c, m/N
    double spoolLapM = 0.0;             ///< positive overlap: the slot opens once h exceeds it, m

    // The electromagnet (eqs. 1-6): L di/dt + r i = U, F_e = K_e i^2.
    double coilTurns = 115.0;          ///< omega_k
    double gapPermeanceH = 1.79e-5;    ///< Lambda_delta, permeance of the working air gap, H
    double gapAreaM2 = 4.11e-4;        ///< S_delta, design section of the air gap, m^2
    double coilResistanceOhm = 240.0;  ///< r, winding plus the amplifier's series resistor, ohm

    // The amplifier: U = U_bias + K_a U_sensor (U = 0 with the regulator off).
    double biasVoltageV = 0.0;     ///< U_bias, the set signal U_z of the paper's fig. 1, V
    double amplifierGain = 137.6;  ///< K_a, V/V

    // The inductive sensor: U_sensor = k_d P_y, with P_y = P (v / S)^y following the chip thickness.
    double sensorGainVPerN = 0.01;  ///< k_d, signal per newton of cutting force, V/N
    double feedExponent = 0.0;      ///< y, exponent of the feed in the radial cutting force (0: the paper's
                                    ///< constant force; 0.6 in the empirical P_y = C t^0.9 s^0.6 v^-0.3)
};

/// The magnetic constant the paper prints for eqs. 4-5 (mu = 1.25e-6), H/m.
inline constexpr double kPaperMagneticConstantHPerM = 1.25e-6;

/// One editable parameter: where it lives in HydraulicFeedParams, its key in the preset
/// ("section.field"), its name in messages, SI unit and the limits validate() enforces.
struct FeedParameterInfo {
    const char* key;
    const char* name;
    const char* unit;
    double HydraulicFeedParams::*member;
    double minValue;
    double maxValue;
};

/// Every parameter of HydraulicFeedParams, in block order (cylinder, slot, spool, magnet, amplifier,
/// sensor): 21 of them.
std::span<const FeedParameterInfo> feedParameters();

/// The parameter with this key ("spool.damping_ratio"); throws std::invalid_argument when unknown.
const FeedParameterInfo& feedParameter(const std::string& key);

/// Throws std::invalid_argument naming the first bad value and its limits, e.g.
/// "spool damping ratio xi = 0.01 is outside 0.05 .. 10".
void validate(const HydraulicFeedParams& params);

/// What the paper's formulas give from the parameters.
struct HydraulicFeedDerived {
    double pistonAreaM2 = 0.0;            ///< F = pi D^2 / 4
    double cylinderGainPerM2 = 0.0;       ///< k_0 = 1 / F (eq. 20)
    double cylinderTimeConstantS = 0.0;   ///< T_c = M k_y / F^2 (eq. 20)
    double pumpFlowM3PerS = 0.0;          ///< Q_y = S F, the flow for the set feed without load
    double slotGainM2PerS = 0.0;          ///< k_s = mu pi d1 sqrt(2 dp / rho) (eq. 15)
    double coilInductanceH = 0.0;         ///< L = omega_k^2 Lambda_delta
    double magnetTimeConstantS = 0.0;     ///< T_k = L / r (eq. 2)
    double armatureGainNPerA2 = 0.0;      ///< K_e = (omega_k Lambda_delta)^2 / (2 mu S_delta) (eq. 5)
    double biasCurrentA = 0.0;            ///< U_bias / r
    double biasSpoolM = 0.0;              ///< K_z K_e i_bias^2: where the bias current holds the spool
    double leakagePerNewtonM3PerS = 0.0;  ///< k_y / F: leakage flow per newton of load (alpha_0 = this x R)
};

/// The derived quantities of valid parameters (call validate() first).
HydraulicFeedDerived deriveFeedQuantities(const HydraulicFeedParams& params);

/// The lap that keeps the slot just shut at the bias current without load (= biasSpoolM): the slot
/// then opens with the first newton of load, m.
double matchedSpoolLap(const HydraulicFeedParams& params);

/// The amplifier gain K_a at which the regulator opens the slot exactly enough to make up the
/// leakage caused by `loadN` with the carriage at the set feed (the paper's design rule: "the slot
/// opens exactly as much as compensates the leakage"). Throws std::invalid_argument when the load is
/// not positive or the slot cannot pass that leakage even fully open.
double designAmplifierGain(const HydraulicFeedParams& params, double loadN);

}  // namespace tt::core
