#include "core/sim/hydraulic/hydraulic_feed_model.h"

#include <algorithm>
#include <cmath>

#include "core/sim/hydraulic/hydraulic_feed_blocks.h"

namespace tt::core {

HydraulicFeedModel::HydraulicFeedModel(const HydraulicFeedParams& params, bool regulatorOn)
    : m_params(params), m_regulatorOn(regulatorOn) {
    validate(m_params);
    m_derived = deriveFeedQuantities(m_params);
}

double HydraulicFeedModel::amplifierVoltage(double loadN, double feedMPerS) const {
    if (!m_regulatorOn) return 0.0;
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

FeedState HydraulicFeedModel::derivative(const FeedState& x, double loadN) const {
    const HydraulicFeedParams& p = m_params;
    const HydraulicFeedDerived& d = m_derived;
    const double voltage = amplifierVoltage(loadN, x.feedMPerS);
    const double force = armatureForce(x.currentA, d.armatureGainNPerA2);
    const double flow = d.pumpFlowM3PerS + regulatorFlow(x.spoolM);
    return {magnetCurrentRate(x.currentA, voltage, d.coilInductanceH, p.coilResistanceOhm), x.spoolVelocityMPerS,
            spoolAcceleration(x.spoolM, x.spoolVelocityMPerS, force, p.spoolTimeConstantS, p.spoolDampingRatio,
                              p.spoolGainMPerN),
            cylinderAcceleration(x.feedMPerS, flow, leakage(loadN), d.cylinderTimeConstantS, d.cylinderGainPerM2)};
}

FeedState HydraulicFeedModel::unloadedState() const {
    return equilibrium(0.0).state;
}

FeedState HydraulicFeedModel::restState() const {
    return staticChain(0.0, 0.0).state;
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
    const double lowest = std::min(0.0, k0 * (m_derived.pumpFlowM3PerS - leakage(loadN))) - 0.01 * s;
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
