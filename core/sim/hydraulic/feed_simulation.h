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
};

/// How long and how finely to simulate.
struct FeedRunOptions {
    static constexpr int kMaxSamples = 200000;
    double durationS = 0.4;  ///< from t = 0, s (0 < duration ≤ 60 s)
    double sampleS = 5e-4;   ///< output interval, s (at most kMaxSamples samples)
    /// Start with the carriage standing (the paper's eq. 22, zero initial conditions) instead of
    /// running at the set feed without load.
    bool fromRest = false;
};

/// A simulated run: the samples and how the feed answered the last load change.
struct FeedRun {
    bool regulatorOn = false;
    std::vector<FeedSample> samples;
    StepMetrics feed;            ///< of the feed after the last load change
    StepMetrics opening;         ///< of the slot's opening after the last load change
    bool slotFullyOpen = false;  ///< at the end: the spool is on its stop
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
