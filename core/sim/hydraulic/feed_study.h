#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/sim/hydraulic/feed_linearisation.h"
#include "core/sim/hydraulic/feed_load_profile.h"
#include "core/sim/hydraulic/feed_simulation.h"
#include "core/sim/hydraulic/hydraulic_feed_params.h"

namespace tt::core {

/// What a study of the feed stabiliser runs: the drive's parameters, the load and how long to simulate.
struct FeedScenario {
    HydraulicFeedParams params;
    FeedLoadProfile load;
    FeedRunOptions run;

    /// The load the feed settles under: the profile's value at the end of the run, N.
    double finalLoadN() const { return load.forceAt(run.durationS); }
};

/// Progress of a long study: (done, total) runs; and whether the caller wants it to stop.
using FeedProgress = std::function<void(int done, int total)>;
using FeedCancelled = std::function<bool()>;

/// Simulates the scenario with the paper's regulator on or off.
FeedRun runFeedScenario(const FeedScenario& scenario, bool regulatorOn, const FeedCancelled& cancelled = {});
/// Simulates the scenario with any regulator (the feedback designed from the scenario's parameters).
FeedRun runFeedScenario(const FeedScenario& scenario, FeedRegulator regulator, const FeedCancelled& cancelled = {});

/// The regulator's parameter a sweep varies.
enum class FeedSweepKind { DampingRatio, AmplifierGain };

/// "xi" or "gain".
const char* toString(FeedSweepKind kind);
/// Parses "xi" or "gain"; throws std::invalid_argument naming the choices.
FeedSweepKind feedSweepKindFromString(const std::string& text);

/// One member of a sweep: the feed's step response with the regulator on at one value.
struct FeedSweepPoint {
    double value = 0.0;  ///< xi; or the amplifier gain K_a in V/V (feed-forward), the factor on K_p (feedback)
    FeedRun run;         ///< with the sweep's regulator
    std::optional<FeedFeedbackDesign> feedback;  ///< the feedback's design at this value (its margins)
    bool stable = false;      ///< the chain linearised at its steady state under the final load has every eigenvalue
                              ///< in the left half-plane, and the gain is below the stability boundary
    bool oscillates = false;  ///< the slot's opening swings past its final value by more than 0.05 % of its
                              ///< largest deviation
};

/// The sweep's default values: xi = 0.2 .. 2 (the paper: below 1 the spool oscillates, slightly above
/// 1 is best); for the feed-forward the design gain for the final load times 0 .. 2, for the feedback
/// the factors 0.25 .. 6 on its designed K_p (beyond its gain margin the loop is unstable).
std::vector<double> defaultSweepValues(FeedSweepKind kind, const FeedScenario& scenario,
                                       FeedRegulator regulator = FeedRegulator::FeedForward);

/// Runs the scenario with `regulator` (feed-forward or feedback) for each value (1 .. 50 of them, each
/// within the parameter's limits; a gain factor of the feedback within 0.01 .. 100). Reports progress after
/// each run; throws FeedSimulationCancelled when `cancelled` says so, std::invalid_argument for the regulator off.
std::vector<FeedSweepPoint> sweepFeed(const FeedScenario& scenario, FeedSweepKind kind,
                                      const std::vector<double>& values,
                                      FeedRegulator regulator = FeedRegulator::FeedForward,
                                      const FeedProgress& progress = {}, const FeedCancelled& cancelled = {});

/// One load of a load sweep: the same step, with each regulator.
struct FeedLoadPoint {
    double loadN = 0.0;
    FeedRun off;
    FeedRun feedForward;
    FeedRun feedback;
    /// The run with `regulator`.
    const FeedRun& of(FeedRegulator regulator) const;
};

/// The load sweep's default loads: 0.5 .. 6 N, with the paper's 3.23 N among them.
std::vector<double> defaultLoadSweepValues();

/// For each load (1 .. 50 of them, 0 .. 1e4 N), the scenario's load replaced by one step to it (at the
/// scenario's last load change, else at 0.02 s), simulated without a regulator, with the feed-forward and
/// with the feedback. Progress after each load; throws FeedSimulationCancelled when `cancelled` says so.
std::vector<FeedLoadPoint> sweepLoad(const FeedScenario& scenario, const std::vector<double>& loadsN,
                                     const FeedProgress& progress = {}, const FeedCancelled& cancelled = {});

/// The stability boundary of the gain, checked by simulation on both sides of it.
struct FeedBoundaryCheck {
    double gainLimit = 0.0;           ///< from the eigenvalues (analyseStability)
    double belowGain = 0.0;           ///< 0.95 x the limit
    double aboveGain = 0.0;           ///< 1.05 x the limit
    double predictedFeedMPerS = 0.0;  ///< the steady feed the linearised analysis gives below the limit
    FeedRun below;
    FeedRun above;
    bool belowSettles = false;   ///< below: settled within 1 % of the predicted feed, slot not fully open
    bool aboveRunsAway = false;  ///< above: the feed ran to the fully open slot
};

/// Simulates the scenario at 0.95 and 1.05 times `gainLimit`, long enough for the slowest mode (up to
/// 60 s), to check the boundary the eigenvalues gave.
FeedBoundaryCheck crossCheckGainLimit(const FeedScenario& scenario, double gainLimit,
                                      const FeedCancelled& cancelled = {});

/// How a 10 % change of one parameter moves the steady feed under the load.
struct FeedSensitivity {
    std::string key;   ///< "spool.gain_m_per_n"
    std::string name;  ///< "spool gain K_z"
    double nominal = 0.0;
    double onMinusPct = 0.0;   ///< regulator on, parameter - 10 %: change of the steady feed, % (of the set feed
                               ///< when the nominal carriage stalls)
    double onPlusPct = 0.0;    ///< regulator on, + 10 %
    double offMinusPct = 0.0;  ///< regulator off, - 10 %
    double offPlusPct = 0.0;   ///< regulator off, + 10 %
    bool fullyOpen = false;    ///< with one of the changes the slot had to open fully
};

/// The steady feed's sensitivity to each non-zero parameter changed by -/+ `change` (0 < change ≤ 0.5,
/// clamped to the parameter's limits), under the load `loadN`, largest effect with `regulator` (the
/// "regulated" columns; the feedback is redesigned for each change, as it would be on the machine)
/// first. The set feed (the reference itself) and parameters at zero (lap, bias, feed exponent of the
/// paper's set-up) are left out.
std::vector<FeedSensitivity> feedSensitivity(const HydraulicFeedParams& params, double loadN, double change = 0.1,
                                             FeedRegulator regulator = FeedRegulator::FeedForward);

}  // namespace tt::core
