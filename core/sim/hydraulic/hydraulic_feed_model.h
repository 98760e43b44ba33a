#pragma once

#include <optional>

#include "core/sim/hydraulic/feed_regulator.h"
#include "core/sim/hydraulic/hydraulic_feed_params.h"

namespace tt::core {

/// The state of the chain (paper 003): magnet current, spool position and velocity, carriage feed, and the
/// feedback regulator's two states (zero with the other regulators).
struct FeedState {
    double currentA = 0.0;            ///< i, coil current, A
    double spoolM = 0.0;              ///< h, spool position from the spring's rest, m
    double spoolVelocityMPerS = 0.0;  ///< dh/dt, m/s
    double feedMPerS = 0.0;           ///< v, carriage velocity (the feed), m/s
    double integralM = 0.0;           ///< z, the integral of the feed error S - v (with back-calculation), m
    double leadM = 0.0;               ///< w, the lead filter's state, 1 / (T_f s + 1) of the PI's output, m
};

/// What the feedback regulator asks for at a state.
struct FeedbackSignals {
    double demandM = 0.0;   ///< m*, the opening the PID demands (before its limits), m
    double appliedM = 0.0;  ///< m* clamped to 0 .. the full opening, m
    double voltageV = 0.0;  ///< the characteriser's output driving the coil, V
};

/// A steady state of the chain under a constant load.
struct FeedEquilibrium {
    FeedState state;
    double openingM = 0.0;             ///< the slot's opening m
    double regulatorFlowM3PerS = 0.0;  ///< k_s m, the flow the regulator adds
    double leakageM3PerS = 0.0;        ///< alpha_0 = k_y R / F
    bool slotFullyOpen = false;        ///< the spool is on its stop: the regulator can give no more
    bool stalled = false;  ///< the delivered flow cannot make up the leakage: the carriage stands on its stop
};

/// The feed stabiliser's chain as one ODE system: sensor -> amplifier -> electromagnet (eq. 1) ->
/// armature force (eq. 6) -> spool (eq. 9) -> slot (eq. 15) -> cylinder (eq. 21), the load R raising
/// the cylinder's leakage (eq. 20) and, through the chip thickness, the force the sensor reads. The
/// sensor's force growing with the feed closes the loop. With the regulator off the magnet is
/// unpowered and the slot stays shut. With the feedback regulator the coil is driven by the PID on the
/// measured feed through the square-root characteriser (FeedFeedbackDesign).
///
/// The carriage stands on a stop at zero feed: the load (the cutting force's feed component and the
/// ways' friction) resists the motion and can hold the carriage, never drive it backwards, so where
/// eq. 21 would give v < 0 the carriage stalls at v = 0 (DECISIONS, "the carriage stalls, it does not run back").
class HydraulicFeedModel {
public:
    /// The paper's regulator on (FeedForward) or off. Throws std::invalid_argument naming the bad parameter.
    HydraulicFeedModel(const HydraulicFeedParams& params, bool regulatorOn);
    /// Any regulator; the feedback is designed from the parameters (designFeedFeedback) unless `feedback`
    /// gives the design. Throws std::invalid_argument naming the bad parameter.
    HydraulicFeedModel(const HydraulicFeedParams& params, FeedRegulator regulator,
                       std::optional<FeedFeedbackDesign> feedback = std::nullopt);

    const HydraulicFeedParams& params() const { return m_params; }
    const HydraulicFeedDerived& derived() const { return m_derived; }
    FeedRegulator regulator() const { return m_regulator; }
    bool regulatorOn() const { return m_regulator != FeedRegulator::Off; }
    /// The feedback's design (only with FeedRegulator::Feedback).
    const std::optional<FeedFeedbackDesign>& feedback() const { return m_feedback; }

    /// The ODE's right-hand side: dx/dt of the chain at state x under the load `loadN`.
    FeedState derivative(const FeedState& x, double loadN) const;

    /// The paper's amplifier output driving the coil, V (0 unless the regulator is the feed-forward).
    double amplifierVoltage(double loadN, double feedMPerS) const;
    /// The feedback regulator's demand and output at a state (zeros with the other regulators).
    FeedbackSignals feedbackSignals(const FeedState& x) const;
    /// The voltage on the coil at a state under a load, whichever the regulator, V.
    double coilVoltage(const FeedState& x, double loadN) const;
    /// Whether the carriage stands on its stop at this state: no feed, and eq. 21 would drive it backwards.
    bool stalled(const FeedState& x, double loadN) const;
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
    /// The feedback's steady state: the set feed, or the fully open slot (stalled if even that is short).
    FeedEquilibrium feedbackEquilibrium(double loadN) const;
    /// The characteriser: the coil voltage that holds the spool at lap + m, V.
    double characteriserVoltage(double openingM) const;

    HydraulicFeedParams m_params;
    HydraulicFeedDerived m_derived;
    FeedRegulator m_regulator;
    std::optional<FeedFeedbackDesign> m_feedback;
};

}  // namespace tt::core
