#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_runner.h"
#include "core/ports/history_store.h"
#include "core/run/shaft_run.h"
#include "core/run/shaft_scenario.h"

namespace tt::core {

/// What `trueturn simulate` asks of the closed loop on the built-in shop.
struct LatheStudyOptions {
    ControllerKind controller = ControllerKind::Lqg;
    std::optional<double> ewmaWeight;         ///< EWMA lambda; none: the setup's (best on the grid when `auto`)
    std::int64_t parts = 20000;               ///< parts counted in the statistics
    std::int64_t warmupParts = 100;           ///< machined first and not counted (controller start-up)
    double speed = 0.0;                       ///< 0: as fast as possible; else simulated s per wall s
    std::vector<double> profileZMm;           ///< where the profile statistics are taken (may be empty)
    HistoryStore* history = nullptr;          ///< the closed run is stored here when given
    RunDescription description;               ///< recorded with the run
    std::optional<ResumePoint> resume;        ///< continue this stored run (the open reference is re-run)
    const std::atomic<bool>* stop = nullptr;  ///< when set: the stored run stops after its current part
    /// Called after every finished part (may be empty): the stage ("closed loop", "open-loop reference"),
    /// the part number and the parts of the run (warm-up included).
    std::function<void(const std::string& stage, std::int64_t part, std::int64_t total)> progress;
    /// The machine of the closed (stored) run; empty: the built-in simulated lathe. The open-loop reference and a
    /// step's reference run on the built-in simulated lathe of the same scenario and seed.
    ShaftMachineFactory machine;
};

/// The study was stopped on request (LatheStudyOptions::stop) after a finished part: what was stored
/// stays stored, and a stored closed run that was interrupted can be resumed.
class StudyInterrupted : public std::runtime_error {
public:
    /// `closedLoop`: the stored run was interrupted (else the open-loop reference, after it completed).
    StudyInterrupted(bool closedLoop, std::optional<std::int64_t> runId, std::int64_t lastPart)
        : std::runtime_error("interrupted after part " + std::to_string(lastPart)),
          closedLoop(closedLoop),
          runId(runId),
          lastPart(lastPart) {}
    bool closedLoop = true;             ///< the closed (stored) run was the one interrupted
    std::optional<std::int64_t> runId;  ///< the stored run, when there is a history
    std::int64_t lastPart = 0;          ///< the last part finished in the interrupted run
};

/// One control point of the study.
struct LatheStudyPoint {
    double xMm = 0.0;
    double varOpenMm2 = 0.0;    ///< true diameter deviation, open loop on the same disturbance
    double varClosedMm2 = 0.0;  ///< with the controller
    double kEff = 0.0;          ///< varOpen / varClosed (paper 000, Table 2); NaN when either is below 1e-12 mm²
    double kEffAnalytic = 0.0;  ///< the controller's design model, closed-loop Lyapunov (NaN when unavailable)
};

/// How much of a step in the plant (PlantMismatch::step) the closed loop leaves in place.
struct StepResidual {
    std::int64_t atPart = 0;
    double sizeMm = 0.0;
    std::optional<int> point;               ///< 0-based; none: the whole part (the mean over the control points)
    std::int64_t fromPart = 0, toPart = 0;  ///< the parts averaged: 3z + 5 after the step, then 20
    /// Mean over those parts of the step's effect on the true error (the run with the step minus the
    /// same run without it, same seed), as % of the step.
    double residualPct = 0.0;
};

/// Parts after a step before its residual is taken: 3z + 5 (z the model's delay); parts averaged: 20.
inline constexpr int kStepSettleFactor = 3;
inline constexpr int kStepSettleParts = 5;
inline constexpr int kStepAveragedParts = 20;

/// The analytic k_eff (closed-loop Lyapunov, summed over the points) of the LQG designed, with the scenario's
/// weights, for the simulated statistical plant itself: the scenario's plant with its gain factor and delay
/// (PlantMismatch). NaN on the physical lathe (no linear model of it) or when the open loop is not stationary.
double truePlantLqgKEff(const ShaftScenario& scenario);

/// Result of a study: variances and k_eff at the control points, and the profile of the finished parts.
struct LatheStudyResult {
    ControllerKind controller = ControllerKind::Lqg;
    int delay = 1;
    std::int64_t parts = 0;        ///< counted in the statistics (LatheStudyOptions::parts)
    std::int64_t warmupParts = 0;  ///< machined, measured and judged before them, not counted in the statistics
    std::optional<double> ewmaWeight;
    std::vector<LatheStudyPoint> points;
    double kEff = 0.0;          ///< sum open / sum closed; NaN when either is below 1e-12 mm² (no variation)
    double kEffAnalytic = 0.0;  ///< NaN when unavailable
    /// The LQG designed for the simulated plant itself (truePlantLqgKEff): what an adaptive loop is judged against.
    double kEffTruePlantLqg = 0.0;
    std::int64_t rejectedValues = 0;
    VerdictCounts verdicts;            ///< the closed run's measured parts by tolerance verdict (warm-up included)
    VerdictCounts warmupVerdicts;      ///< the warm-up's share of `verdicts`
    std::int64_t toleranceAlarms = 0;  ///< its out-of-tolerance alarms
    /// Profile of the closed run's parts: mean and standard deviation of the true diameter error at
    /// profileZMm over parts [profileFromPart, profileToPart] (after the first 2z + 5, the loop's start-up).
    std::vector<double> profileZMm, profileMeanMm, profileStdMm;
    std::int64_t profileFromPart = 0, profileToPart = 0;
    std::optional<std::int64_t> runId;
    SimulationOutcome outcome;
    std::optional<StepResidual> step;              ///< when the scenario's plant has a step
    std::vector<RecordedAlarm> modelAlarms;        ///< the mismatch monitor's alarms in the closed run
    std::vector<AdaptationRecord> adaptations;     ///< what the adaptive loop did in the closed run
    std::vector<RecordedAlarm> adaptationNotices;  ///< its notices to the operator (refusals of the identification too)
    double maxCorrectionMm = 0.0;                  ///< the closed run's largest |correction| sent, radial mm
    double maxCorrectionStepMm = 0.0;              ///< and its largest change between parts, radial mm
    double maxSwitchStepMm = 0.0;  ///< its largest change within kSwitchWatchParts of a controller switch
    int switches = 0;              ///< controller switches of the adaptive loop
    /// Per control point, the closed run's systematic error: the mean true diameter deviation over parts
    /// [systematicFromPart, last] (after the loop's start-up of 2z + 5 parts), mm.
    std::vector<double> systematicMm;
    std::int64_t systematicFromPart = 0;
};

/// Runs the closed loop of `scenario` (planned by planShaftRun: with the feed-forward unless open) with the
/// chosen controller on the simulated shop seeded by `seed`, and the open loop (no feed-forward, no
/// correction) on the same shop for the reference variances; adds the analytic k_eff of the design model. Throws
/// std::invalid_argument on bad options and std::runtime_error when the run stops before its last part (the reason).
LatheStudyResult runLatheStudy(const ShaftScenario& scenario, std::uint64_t seed, const LatheStudyOptions& options);

}  // namespace tt::core
