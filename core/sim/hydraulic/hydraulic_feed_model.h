#pragma once

#include "core/sim/hydraulic/hydraulic_feed_params.h"

namespace tt::core {

/// The state of the chain (paper 003): magnet current, spool position and velocity, carriage feed.
struct FeedState {
    double currentA = 0.0;            ///< i, coil current, A
    double spoolM = 0.0;              ///< h, spool position from the spring's rest, m
    double spoolVelocityMPerS = 0.0;  ///< dh/dt, m/s
    double feedMPerS = 0.0;           ///< v, carriage velocity (the feed), m/s
};

/// A steady state of the chain under a constant load.
struct FeedEquilibrium {
    FeedState state;
    double openingM = 0.0;             ///< the slot's opening m
    double regulatorFlowM3PerS = 0.0;  ///< k_s m, the flow the regulator adds
    double leakageM3PerS = 0.0;        ///< alpha_0 = k_y R / F
    bool slotFullyOpen = false;        ///< the spool is on its stop: the regulator can give no more
};

/// The feed stabiliser's chain as one ODE system: sensor -> amplifier -> electromagnet (eq. 1) ->
/// armature force (eq. 6) -> spool (eq. 9) -> slot (eq. 15) -> cylinder (eq. 21), the load R raising
/// the cylinder's leakage (eq. 20) and, through the chip thickness, the force the sensor reads. The
/// sensor's force growing with the feed closes the loop. With the regulator off the magnet is
/// unpowered and the slot stays shut.
class HydraulicFeedModel {
public:
    /// Throws std::invalid_argument naming the bad parameter (validate()).
    HydraulicFeedModel(const HydraulicFeedParams& params, bool regulatorOn);

    const HydraulicFeedParams& params() const { return m_params; }
    const HydraulicFeedDerived& derived() const { return m_derived; }
    bool regulatorOn() const { return m_regulatorOn; }

    /// The ODE's right-hand side: dx/dt of the chain at state x under the load `loadN`.
    FeedState derivative(const FeedState& x, double loadN) const;

    /// The amplifier's output driving the coil, V (0 with the regulator off).
    double amplifierVoltage(double loadN, double feedMPerS) const;
    /// The slot's opening for the spool position, m.
    double opening(double spoolM) const;
    /// The flow the regulator adds for the spool position, m^3/s.
    double regulatorFlow(double spoolM) const;
    /// The cylinder's leakage under the load, m^3/s.
    double leakage(double loadN) const;

    /// Running without load: the steady state under zero load (the set feed when the lap matches the bias).
    FeedState unloadedState() const;
    /// The carriage standing without load, the magnet at its bias current (the paper's eq. 22 starts here).
    FeedState restState() const;

    /// The steady state under the constant load `loadN`: the lowest equilibrium of the feed, the one the
    /// carriage settles at when the load arrives at the set feed (above it the regulator's positive
    /// feedback through the cutting force has an unstable one). When the regulator's feedback is too
    /// strong for any equilibrium with the slot partly open, the slot is fully open in the result.
    FeedEquilibrium equilibrium(double loadN) const;

private:
    /// The chain's steady state for a given feed (current, spool and flow follow from it).
    FeedEquilibrium staticChain(double loadN, double feedMPerS) const;

    HydraulicFeedParams m_params;
    HydraulicFeedDerived m_derived;
    bool m_regulatorOn;
};

}  // namespace tt::core
