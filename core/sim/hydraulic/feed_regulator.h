#pragma once

#include <string>

#include "core/control/continuous_margins.h"
#include "core/sim/hydraulic/hydraulic_feed_params.h"

namespace tt::core {

/// Which regulator drives the electromagnet of the feed stabiliser (paper 003).
enum class FeedRegulator {
    Off,          ///< the magnet unpowered, the slot shut: the pump's flow alone (the paper's 2.8e-4 m/s)
    FeedForward,  ///< the paper's: the amplified force signal U = U_0 + K_a k_d P_y drives the magnet
    Feedback,     ///< PID on the measured feed through a square-root characteriser (designFeedFeedback)
};

/// "off", "feedforward" or "feedback".
const char* toString(FeedRegulator regulator);
/// Parses "off", "feedforward" or "feedback"; throws std::invalid_argument naming the choices.
FeedRegulator feedRegulatorFromString(const std::string& text);

/// What the feedback design aims at (DECISIONS, "Feedback of the feed").
struct FeedFeedbackTargets {
    double phaseMarginDeg = 50.0;  ///< the loop gain is set for this phase margin, deg
    double minGainMargin = 2.5;    ///< ... unless that leaves less gain margin than this (8 dB)
    /// T_i = T_c / this: the integral zero above the cylinder's pole, so the feedback moves the cylinder's
    /// slow mode instead of leaving it in the answer to a load step (settling within 3 T_c).
    double integralRateFactor = 1.5;
    double derivativeFilterRatio = 10.0;  ///< T_f = T_d / this (the classical N = 10)
};

/// The feedback regulator of the feed: the measured feed v is compared with the set feed S, a series PID
/// C(s) = K_p (T_i s + 1)(T_d s + 1) / (T_i s (T_f s + 1)) turns the error into the slot opening m* it
/// demands (clamped to 0 .. the full opening, with back-calculation against wind-up), and a square-root
/// characteriser U = r sqrt((lap + m*) / (K_z K_e)) inverts the magnet's square law (eq. 6) and the spring
/// (eq. 9), so the spool settles where m* asks at any load. Linearised, the chain from m* to v is the
/// paper's eq. 17 (magnet, spool, slot) times the cylinder's eq. 22, whatever the operating point:
///   G(s) = k_s k_0 / ((T_k s + 1)(T_z^2 s^2 + 2 xi T_z s + 1)(T_c s + 1)).
struct FeedFeedbackDesign {
    double gainS = 0.0;          ///< K_p: slot opening demanded per feed error, m per (m/s), i.e. s
    double integralTimeS = 0.0;  ///< T_i, s
    double leadTimeS = 0.0;      ///< T_d: the spool's slower time constant, s
    double filterTimeS = 0.0;    ///< T_f, s
    double trackingTimeS = 0.0;  ///< T_t of the back-calculation, sqrt(T_i T_d), s
    FeedFeedbackTargets targets;
    RationalTransfer plant;       ///< G(s): opening demand (m) -> feed (m/s)
    RationalTransfer controller;  ///< C(s): feed error (m/s) -> opening demand (m)
    RationalTransfer loop;        ///< L(s) = C(s) G(s)
    ContinuousMargins margins;    ///< of L, with its closed-loop poles
};

/// The linearised chain from the demanded slot opening to the feed (paper eqs. 2, 13, 15, 22 in series;
/// the magnet's square law cancelled by the characteriser), (m/s) per m.
RationalTransfer feedPlantTransfer(const HydraulicFeedParams& params);

/// Designs the feedback for valid parameters: T_d = the spool's slower time constant (T_z (xi + sqrt(xi^2 - 1))
/// for xi >= 1, 2 xi T_z below), T_i = T_c / integralRateFactor, T_f = T_d / derivativeFilterRatio, and K_p
/// for the target phase margin (at the lowest frequency where the loop's phase reaches it), lowered if the
/// gain margin would fall below its minimum. Margins from continuousMargins on 0.1 .. 1e6 rad/s.
FeedFeedbackDesign designFeedFeedback(const HydraulicFeedParams& params, const FeedFeedbackTargets& targets = {});

/// The same design with K_p multiplied by `factor` (> 0): its loop and margins recomputed (a gain sweep).
FeedFeedbackDesign scaledFeedback(const FeedFeedbackDesign& design, double factor);

}  // namespace tt::core
