#include "core/sim/hydraulic/hydraulic_feed_model.h"

#include <algorithm>
#include <cmath>

#include "core/sim/hydraulic/hydraulic_feed_blocks.h"

namespace tt::core {

HydraulicFeedModel::HydraulicFeedModel(const HydraulicFeedParams& params, bool regulatorOn)
    : HydraulicFeedModel(params, regulatorOn ? FeedRegulator::FeedForward : FeedRegulator::Off) {}

HydraulicFeedModel::HydraulicFeedModel(const HydraulicFeedParams& params, FeedRegulator regulator,
                                       std::optional<FeedFeedbackDesign> feedback)
    : m_params(params), m_regulator(regulator) {
    validate(m_params);
    m_derived = deriveFeedQuantities(m_params);
    if (m_regulator == FeedRegulator::Feedback)
        m_feedback = feedback ? std::move(feedback) : designFeedFeedback(m_params);
}

double HydraulicFeedModel::amplifierVoltage(double loadN, double feedMPerS) const {
    if (m_regulator != FeedRegulator::FeedForward) return 0.0;
    const double force = sensedForce(loadN, feedMPerS, m_params.setFeedMPerS, m_params.feedExponent);
    return m_params.biasVoltageV + m_params.amplifierGain * m_params.sensorGainVPerN * force;
}

double HydraulicFeedModel::opening(double spoolM) const {
    return slotOpening(spoolM, m_params.spoolLapM, m_params.maxOpeningM);
}

double HydraulicFeedModel::regulatorFlow(double spoolM) const {
    return slotFlow(opening(spoolM), m_derived.slotGainM2PerS);
}

double HydraulicFeedModel::leakage(double loadN) const {
    return leakageFlow(loadN, m_derived.leakagePerNewtonM3PerS);
}

double HydraulicFeedModel::characteriserVoltage(double openingM) const {
    const double forceN = (m_params.spoolLapM + openingM) / m_params.spoolGainMPerN;
    return m_params.coilResistanceOhm * std::sqrt(std::max(0.0, forceN) / m_derived.armatureGainNPerA2);
}

FeedbackSignals HydraulicFeedModel::feedbackSignals(const FeedState& x) const {
    if (!m_feedback) return {};
    const FeedFeedbackDesign& c = *m_feedback;
    const double error = m_params.setFeedMPerS - x.feedMPerS;
    const double pi = c.gainS * (error + x.integralM / c.integralTimeS);
    const double ratio = c.leadTimeS / c.filterTimeS;
    FeedbackSignals s;
    s.demandM = ratio * pi + (1.0 - ratio) * x.leadM;
    s.appliedM = std::clamp(s.demandM, 0.0, m_params.maxOpeningM);
    s.voltageV = characteriserVoltage(s.appliedM);
    return s;
}

double HydraulicFeedModel::coilVoltage(const FeedState& x, double loadN) const {
    return m_regulator == FeedRegulator::Feedback ? feedbackSignals(x).voltageV : amplifierVoltage(loadN, x.feedMPerS);
}

bool HydraulicFeedModel::stalled(const FeedState& x, double loadN) const {
    if (x.feedMPerS > 1e-9 * m_params.setFeedMPerS) return false;
    const double flow = m_derived.pumpFlowM3PerS + regulatorFlow(x.spoolM);
    return cylinderAcceleration(x.feedMPerS, flow, leakage(loadN), m_derived.cylinderTimeConstantS,
                                m_derived.cylinderGainPerM2) < 0.0;
}

FeedState HydraulicFeedModel::derivative(const FeedState& x, double loadN) const {
    const HydraulicFeedParams& p = m_params;
    const HydraulicFeedDerived& d = m_derived;
    const double voltage = coilVoltage(x, loadN);
    const double force = armatureForce(x.currentA, d.armatureGainNPerA2);
    const double flow = d.pumpFlowM3PerS + regulatorFlow(x.spoolM);
    double acceleration =
        cylinderAcceleration(x.feedMPerS, flow, leakage(loadN), d.cylinderTimeConstantS, d.cylinderGainPerM2);
    // The stop: at zero feed the carriage stalls, never runs backwards; an integration step that overshot
    // below zero is pulled back with the cylinder's own time constant.
    if (x.feedMPerS <= 0.0) acceleration = std::max(acceleration, -x.feedMPerS / d.cylinderTimeConstantS);
    FeedState dx{magnetCurrentRate(x.currentA, voltage, d.coilInductanceH, p.coilResistanceOhm), x.spoolVelocityMPerS,
                 spoolAcceleration(x.spoolM, x.spoolVelocityMPerS, force, p.spoolTimeConstantS, p.spoolDampingRatio,
                                   p.spoolGainMPerN),
                 acceleration};
    if (m_feedback) {
        const FeedFeedbackDesign& c = *m_feedback;
        const FeedbackSignals s = feedbackSignals(x);
        const double error = p.setFeedMPerS - x.feedMPerS;
        const double pi = c.gainS * (error + x.integralM / c.integralTimeS);
        // Back-calculation (Astrom & Hagglund): the integral is pulled back while the demand is clamped.
        dx.integralM = error + c.integralTimeS / (c.gainS * c.trackingTimeS) * (s.appliedM - s.demandM);
        dx.leadM = (pi - x.leadM) / c.filterTimeS;
    }
    return dx;
}

FeedState HydraulicFeedModel::unloadedState() const {
    return equilibrium(0.0).state;
}

FeedState HydraulicFeedModel::restState() const {
    if (m_regulator == FeedRegulator::Feedback) {
        FeedState x;  // the controller at rest, the slot shut, the carriage standing
        x.currentA = characteriserVoltage(0.0) / m_params.coilResistanceOhm;
        x.spoolM = m_params.spoolLapM;
        return x;
    }
    return staticChain(0.0, 0.0).state;
}

FeedEquilibrium HydraulicFeedModel::feedbackEquilibrium(double loadN) const {
    const FeedFeedbackDesign& c = *m_feedback;
    const HydraulicFeedDerived& d = m_derived;
    FeedEquilibrium e;
    e.leakageM3PerS = leakage(loadN);
    e.openingM = std::min(e.leakageM3PerS / d.slotGainM2PerS, m_params.maxOpeningM);
    e.regulatorFlowM3PerS = slotFlow(e.openingM, d.slotGainM2PerS);
    e.slotFullyOpen = e.openingM >= m_params.maxOpeningM * (1.0 - 1e-9);
    const double balance = d.cylinderGainPerM2 * (d.pumpFlowM3PerS + e.regulatorFlowM3PerS - e.leakageM3PerS);
    FeedState& x = e.state;
    x.feedMPerS = e.slotFullyOpen ? std::max(0.0, balance) : m_params.setFeedMPerS;
    e.stalled = e.slotFullyOpen && balance < 0.0;
    const double error = m_params.setFeedMPerS - x.feedMPerS;
    // On the stop, the back-calculation holds the demand above the full opening by K_p T_t e / T_i.
    const double demand =
        e.slotFullyOpen ? m_params.maxOpeningM + c.gainS * c.trackingTimeS * error / c.integralTimeS : e.openingM;
    x.integralM = c.integralTimeS * (demand / c.gainS - error);
    x.leadM = demand;
    x.currentA = characteriserVoltage(e.openingM) / m_params.coilResistanceOhm;
    x.spoolM = m_params.spoolGainMPerN * armatureForce(x.currentA, d.armatureGainNPerA2);
    return e;
}

FeedEquilibrium HydraulicFeedModel::staticChain(double loadN, double feedMPerS) const {
    FeedEquilibrium e;
    e.state.feedMPerS = feedMPerS;
    e.state.currentA = amplifierVoltage(loadN, feedMPerS) / m_params.coilResistanceOhm;
    e.state.spoolM = m_params.spoolGainMPerN * armatureForce(e.state.currentA, m_derived.armatureGainNPerA2);
    e.openingM = opening(e.state.spoolM);
    e.regulatorFlowM3PerS = regulatorFlow(e.state.spoolM);
    e.leakageM3PerS = leakage(loadN);
    e.slotFullyOpen = e.openingM >= m_params.maxOpeningM * (1.0 - 1e-9);
    return e;
}

FeedEquilibrium HydraulicFeedModel::equilibrium(double loadN) const {
    if (m_feedback) return feedbackEquilibrium(loadN);
    // g(v) = k_0 (Q_y + Q_r(v) - alpha_0) - v is the cylinder's steady-state balance for a feed v
    // with the rest of the chain at rest. It is positive far below every equilibrium (no regulator
    // flow there, v < k_0 (Q_y - alpha_0)) and negative far above (the slot's flow is bounded), so the
    // lowest crossing from + to - is the stable equilibrium the feed reaches from below.
    const double k0 = m_derived.cylinderGainPerM2;
    auto balance = [&](double v) {
        const FeedEquilibrium e = staticChain(loadN, v);
        return k0 * (m_derived.pumpFlowM3PerS + e.regulatorFlowM3PerS - e.leakageM3PerS) - v;
    };
    const double s = m_params.setFeedMPerS;
    if (balance(0.0) <= 0.0) {  // the carriage stands on its stop: the flow cannot make up the leakage
        FeedEquilibrium e = staticChain(loadN, 0.0);
        e.stalled = balance(0.0) < 0.0;
        return e;
    }
    const double lowest = 0.0;
    const double highest = k0 * (m_derived.pumpFlowM3PerS + m_derived.slotGainM2PerS * m_params.maxOpeningM) + 0.01 * s;
    constexpr int kGrid = 4000;  // feeds closer than (highest - lowest) / 4000 are one equilibrium
    double a = lowest;
    double ga = balance(a);
    for (int k = 1; k <= kGrid; ++k) {
        double b = lowest + (highest - lowest) * k / kGrid;
        const double gb = balance(b);
        if (ga > 0.0 && gb <= 0.0) {
            for (int it = 0; it < 200 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++it) {
                const double mid = 0.5 * (a + b);
                (balance(mid) > 0.0 ? a : b) = mid;
            }
            return staticChain(loadN, 0.5 * (a + b));
        }
        a = b;
        ga = gb;
    }
    // Unreachable for valid parameters (g(highest) < 0); the fully open slot is the answer then.
    return staticChain(loadN, highest);
}

}  // namespace tt::core
