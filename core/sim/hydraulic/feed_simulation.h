#pragma once

#include <functional>
#include <stdexcept>
#include <vector>

#include "core/sim/hydraulic/feed_load_profile.h"
#include "core/sim/hydraulic/hydraulic_feed_model.h"
#include "core/sim/hydraulic/step_metrics.h"

namespace tt::core {

/// One sample of the simulated feed drive.
struct FeedSample {
    double timeS = 0.0;
    double loadN = 0.0;                ///< the load on the carriage, N
    double feedMPerS = 0.0;            ///< v, m/s
    double currentA = 0.0;             ///< magnet current i, A
    double spoolM = 0.0;               ///< spool position h, m
    double openingM = 0.0;             ///< the slot's opening m, m
    double regulatorFlowM3PerS = 0.0;  ///< the flow the regulator adds, m^3/s
    double demandM = 0.0;              ///< the feedback's demanded opening m* before its limits, m (0 otherwise)
    bool stalled = false;              ///< the carriage stands on its stop (HydraulicFeedModel::stalled)
};

/// What a run met that the operator must know: a state on a clamp, a saturated regulator, a missed feed.
enum class FeedWarningKind {
    CarriageStalled,  ///< the carriage stood on its stop: the flow could not make up the leakage
    SlotFullyOpen,    ///< the spool on its stop, the slot fully open: the regulator could give no more
    SlotShut,         ///< the feedback asked for less than a shut slot: it could take no flow away
    FeedOffSet,       ///< the feed at the end of the run is outside the band around the set feed
};

/// "carriage_stalled", "slot_fully_open", "slot_shut", "feed_off_set".
const char* toString(FeedWarningKind kind);

/// One kind of warning in a run: when it first and last held (at the samples), and for how long in all.
struct FeedWarning {
    FeedWarningKind kind = FeedWarningKind::FeedOffSet;
    double fromS = 0.0;
    double toS = 0.0;
    double durationS = 0.0;  ///< the samples' time in that state, s
    double value = 0.0;      ///< FeedOffSet: the final feed's deviation from the set feed, %; else 0
};

/// How well the feed held the set feed while the load changed: the largest deviation outside the
/// transients, i.e. leaving out `excludedS` after the start of every load change (3 T_c: the paper's
/// t_c = 3T of the cylinder) and after a start from rest.
struct FeedHold {
    double bandPct = 3.0;              ///< the band around the set feed, %
    double excludedS = 0.0;            ///< left out after each change, s
    double largestDeviationPct = 0.0;  ///< (v - S) / S at its largest magnitude, signed, %
    double atS = 0.0;                  ///< when, s
    bool withinBand = true;            ///< |largest deviation| <= band
};

/// How long and how finely to simulate.
struct FeedRunOptions {
    static constexpr int kMaxSamples = 200000;
    double durationS = 0.4;  ///< from t = 0, s (0 < duration ≤ 60 s)
    double sampleS = 5e-4;   ///< output interval, s (at most kMaxSamples samples)
    /// Start with the carriage standing (the paper's eq. 22, zero initial conditions) instead of
    /// running at the set feed without load.
    bool fromRest = false;
    double bandPct = 3.0;  ///< the band around the set feed for FeedHold and FeedOffSet, % (0 < band <= 100)
};

/// A simulated run: the samples and how the feed answered the last load change.
struct FeedRun {
    FeedRegulator regulator = FeedRegulator::Off;
    bool regulatorOn = false;
    std::vector<FeedSample> samples;
    StepMetrics feed;            ///< of the feed after the last load change
    StepMetrics opening;         ///< of the slot's opening after the last load change
    bool slotFullyOpen = false;  ///< at the end: the spool is on its stop
    double setFeedMPerS = 0.0;   ///< S, m/s
    double deviationPct = 0.0;   ///< the final feed's deviation from S, %
    FeedHold hold;
    std::vector<FeedWarning> warnings;  ///< in the order of FeedWarningKind, each kind at most once
};

/// Thrown by simulateFeed when its `cancelled` callback says so.
class FeedSimulationCancelled : public std::runtime_error {
public:
    FeedSimulationCancelled() : std::runtime_error("the simulation was cancelled") {}
};

/// Simulates the chain from the unloaded state (carriage at the set feed, or standing) under `load`, integrating
/// the ODE with the adaptive Dormand-Prince stepper between the load's breakpoints (a step never
/// falls inside a step of the integrator). `cancelled`, when set, is asked at every sample. Throws
/// std::invalid_argument for options outside their limits.
FeedRun simulateFeed(const HydraulicFeedModel& model, const FeedLoadProfile& load, const FeedRunOptions& options,
                     const std::function<bool()>& cancelled = {});

}  // namespace tt::core
