#include "core/sim/hydraulic/hydraulic_feed_params.h"

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

using P = HydraulicFeedParams;

// Limits: wide enough for any finishing lathe's hydraulic feed, narrow enough that the model stays
// meaningful (xi below 0.05 would ring for seconds; a feed exponent above 1.5 is no cutting law).
const std::array<FeedParameterInfo, 21> kParameters = {{
    {"cylinder.mass_kg", "carriage mass M", "kg", &P::carriageMassKg, 1.0, 1.0e4},
    {"cylinder.piston_diameter_m", "piston diameter D", "m", &P::pistonDiameterM, 0.01, 1.0},
    {"cylinder.leakage_m3_per_s_pa", "leakage coefficient k_y", "m^3/(s Pa)", &P::leakageM3PerSPa, 1.0e-12, 1.0e-5},
    {"cylinder.set_feed_m_per_s", "set feed S", "m/s", &P::setFeedMPerS, 1.0e-5, 0.1},
    {"slot.discharge_coefficient", "discharge coefficient mu", "", &P::dischargeCoefficient, 0.5, 0.9},
    {"slot.plunger_diameter_m", "plunger diameter d1", "m", &P::plungerDiameterM, 1.0e-3, 0.05},
    {"slot.pressure_drop_pa", "pressure drop across the slot", "Pa", &P::pressureDropPa, 1.0e4, 1.0e7},
    {"slot.oil_density_kg_per_m3", "oil density rho", "kg/m^3", &P::oilDensityKgPerM3, 700.0, 1100.0},
    {"slot.max_opening_m", "full slot opening", "m", &P::maxOpeningM, 1.0e-5, 5.0e-3},
    {"spool.time_constant_s", "spool time constant T_z", "s", &P::spoolTimeConstantS, 1.0e-4, 0.5},
    {"spool.damping_ratio", "spool damping ratio xi", "", &P::spoolDampingRatio, 0.05, 10.0},
    {"spool.gain_m_per_n", "spool gain K_z", "m/N", &P::spoolGainMPerN, 1.0e-7, 1.0e-2},
    {"spool.lap_m", "spool lap", "m", &P::spoolLapM, 0.0, 0.05},
    {"magnet.turns", "coil turns", "", &P::coilTurns, 10.0, 1.0e4},
    {"magnet.gap_permeance_h", "air-gap permeance", "H", &P::gapPermeanceH, 1.0e-8, 1.0e-3},
    {"magnet.gap_area_m2", "air-gap section", "m^2", &P::gapAreaM2, 1.0e-6, 1.0e-2},
    {"magnet.resistance_ohm", "coil resistance r", "ohm", &P::coilResistanceOhm, 0.1, 1000.0},
    {"amplifier.bias_v", "amplifier bias voltage", "V", &P::biasVoltageV, 0.0, 48.0},
    {"amplifier.gain", "amplifier gain K_a", "V/V", &P::amplifierGain, 0.0, 1.0e5},
    {"sensor.gain_v_per_n", "sensor gain k_d", "V/N", &P::sensorGainVPerN, 1.0e-6, 10.0},
    {"sensor.feed_exponent", "feed exponent of the radial force y", "", &P::feedExponent, 0.0, 1.5},
}};

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

std::span<const FeedParameterInfo> feedParameters() {
    return kParameters;
}

const FeedParameterInfo& feedParameter(const std::string& key) {
    for (const FeedParameterInfo& p : kParameters)
        if (key == p.key) return p;
    throw std::invalid_argument("unknown hydraulic feed parameter '" + key + "'");
}

void validate(const HydraulicFeedParams& params) {
    for (const FeedParameterInfo& p : kParameters) {
        const double v = params.*(p.member);
        const std::string unit = *p.unit ? std::string(" ") + p.unit : std::string();
        if (!std::isfinite(v)) throw std::invalid_argument(std::string(p.name) + " is not a finite number");
        if (v < p.minValue || v > p.maxValue)
            throw std::invalid_argument(std::string(p.name) + " = " + number(v) + unit + " is outside " +
                                        number(p.minValue) + " .. " + number(p.maxValue) + unit);
    }
    const HydraulicFeedDerived d = deriveFeedQuantities(params);
    if (d.biasSpoolM > 0.05)
        throw std::invalid_argument("the amplifier bias " + number(params.biasVoltageV) + " V pulls the spool " +
                                    number(d.biasSpoolM * 1e3) +
                                    " mm: more than the 50 mm a spool can travel; lower the bias");
}

HydraulicFeedDerived deriveFeedQuantities(const HydraulicFeedParams& p) {
    HydraulicFeedDerived d;
    d.pistonAreaM2 = std::numbers::pi * p.pistonDiameterM * p.pistonDiameterM / 4.0;
    d.cylinderGainPerM2 = 1.0 / d.pistonAreaM2;
    d.cylinderTimeConstantS = p.carriageMassKg * p.leakageM3PerSPa / (d.pistonAreaM2 * d.pistonAreaM2);
    d.pumpFlowM3PerS = p.setFeedMPerS * d.pistonAreaM2;
    d.slotGainM2PerS = p.dischargeCoefficient * std::numbers::pi * p.plungerDiameterM *
                       std::sqrt(2.0 * p.pressureDropPa / p.oilDensityKgPerM3);
    d.coilInductanceH = p.coilTurns * p.coilTurns * p.gapPermeanceH;
    d.magnetTimeConstantS = d.coilInductanceH / p.coilResistanceOhm;
    const double flux = p.coilTurns * p.gapPermeanceH;
    d.armatureGainNPerA2 = flux * flux / (2.0 * kPaperMagneticConstantHPerM * p.gapAreaM2);
    d.biasCurrentA = p.biasVoltageV / p.coilResistanceOhm;
    d.biasSpoolM = p.spoolGainMPerN * d.armatureGainNPerA2 * d.biasCurrentA * d.biasCurrentA;
    d.leakagePerNewtonM3PerS = p.leakageM3PerSPa / d.pistonAreaM2;
    return d;
}

double matchedSpoolLap(const HydraulicFeedParams& params) {
    return deriveFeedQuantities(params).biasSpoolM;
}

double designAmplifierGain(const HydraulicFeedParams& p, double loadN) {
    if (!(loadN > 0.0) || !std::isfinite(loadN))
        throw std::invalid_argument("design load " + number(loadN) + " N: must be > 0");
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const double openingM = d.leakagePerNewtonM3PerS * loadN / d.slotGainM2PerS;
    if (openingM > p.maxOpeningM)
        throw std::invalid_argument("the leakage under " + number(loadN) + " N needs a slot opening of " +
                                    number(openingM * 1e3) + " mm, more than the full opening " +
                                    number(p.maxOpeningM * 1e3) + " mm");
    const double forceN = (p.spoolLapM + openingM) / p.spoolGainMPerN;
    const double voltageV = std::sqrt(forceN / d.armatureGainNPerA2) * p.coilResistanceOhm;
    if (voltageV < p.biasVoltageV)
        throw std::invalid_argument("the bias " + number(p.biasVoltageV) +
                                    " V alone opens the slot further than the leakage under " + number(loadN) +
                                    " N needs: lower the bias or lengthen the spool lap");
    return (voltageV - p.biasVoltageV) / (p.sensorGainVPerN * loadN);
}

}  // namespace tt::core
