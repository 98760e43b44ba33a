#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/loop/loop_events.h"
#include "core/loop/loop_runner.h"
#include "core/ports/history_store.h"
#include "core/run/shaft_run_builder.h"
#include "core/run/shaft_scenario.h"

namespace tt::core {

class LoopEngine;

/// A machine a headless run goes on instead of the built-in simulated lathe. The engine knows no device: the
/// runtime or the app makes it (the LinuxCNC lathe of `trueturn simulate --cnc`). A machine whose time is the wall
/// clock (no ShaftMachine::jumpTo) is stepped as it is polled, every 10 ms, as the Run page's loop thread does.
struct ShaftMachineFactory {
    /// Makes the machine for one run of `scenario`, its random sources seeded by `seed`; called in the run's
    /// thread. Empty: the built-in simulated lathe.
    std::function<std::unique_ptr<ShaftMachine>(const ShaftScenario& scenario, std::uint64_t seed)> make;
    /// Called after every engine step on a wall-clock machine and once when the run ends, while the machine lives
    /// (may be empty): takes what the machine has to report (its incidents, the corrections it wrote).
    std::function<void(ShaftMachine& machine, const LoopEngine& engine)> poll;
};

/// One closed-loop run on the built-in simulated shop, headless (what `trueturn simulate` runs): the
/// loop engine on the shop's ports with a virtual clock, optionally paced and stored.
struct LatheRunSpec {
    ShaftScenario scenario;                   ///< the scenario
    std::uint64_t seed = 1;                   ///< every random source of the simulated shop
    ShaftRunPlan plan;                        ///< loop.lastPartNumber = the parts of the run
    HistoryStore* history = nullptr;          ///< none: nothing is stored
    RunDescription description;               ///< recorded when the run starts
    std::optional<ResumePoint> resume;        ///< continue this stored run instead of starting one
    double speed = 0.0;                       ///< 0: as fast as possible; else simulated s per wall s
    LoopListener* listener = nullptr;         ///< also receives the engine's events
    std::int64_t warmupParts = 0;             ///< the first parts, whose verdicts are also counted apart
    std::vector<double> profileZMm;           ///< where to sample each finished part's true profile
    const std::atomic<bool>* stop = nullptr;  ///< when set: finish the part on the machine and stop (resumable)
    ShaftMachineFactory machine;              ///< empty: the built-in simulated lathe; else no resume, no pacing
};

/// An alarm of the run as the loop raised it (its stable kind, the part, the notice with its data).
struct RecordedAlarm {
    std::int64_t part = 0;
    std::string kind;
    Notice notice;
};

/// What the run produced: the true (simulated) diameter deviation of every part at the control points
/// and at the profile positions, indexed by part number - 1.
struct LatheRunRecord {
    SimulationOutcome outcome;
    std::optional<std::int64_t> runId;
    std::vector<Eigen::VectorXd> pointDeviationMm;    ///< per part: at the control points
    std::vector<Eigen::VectorXd> profileDeviationMm;  ///< per part: at LatheRunSpec::profileZMm
    std::vector<bool> seen;                           ///< per part: finished (or re-created after a resume)
    std::int64_t rejectedValues = 0;                  ///< measured values the loop or the controller rejected
    VerdictCounts verdicts;                           ///< measured parts by tolerance verdict (this session)
    VerdictCounts warmupVerdicts;                     ///< of them, parts 1 .. LatheRunSpec::warmupParts
    std::int64_t toleranceAlarms = 0;                 ///< out-of-tolerance alarms (one per point out of tolerance)
    std::vector<RecordedAlarm> modelAlarms;           ///< the mismatch monitor's alarms ("model-mismatch")
    std::vector<AdaptationRecord> adaptations;        ///< what the adaptive loop did (fallback, adaptations, ...)
    std::vector<RecordedAlarm> adaptationNotices;     ///< every notice of the adaptive loop (refusals included)
    double maxCorrectionMm = 0.0;                     ///< largest |correction| sent to the CNC, radial mm
    double maxCorrectionStepMm = 0.0;                 ///< largest change of a point's correction between parts
    /// Largest change of a point's correction between parts from a controller switch (the adaptive loop's) to
    /// kSwitchWatchParts after it, radial mm; and how many switches there were.
    double maxSwitchStepMm = 0.0;
    int switches = 0;
};

/// Parts after a controller switch whose correction steps count as the switch's.
inline constexpr int kSwitchWatchParts = 20;

/// Runs the loop (built by buildShaftRun on a SimulatedLathe whose time jumps from event to event, or on the
/// machine of LatheRunSpec::machine) until its last part is machined and measured, a fault, or nothing can happen
/// (a wall-clock machine: until the run completes, faults or is stopped). On resume the stored parts
/// are re-created from their stored corrections (the simulator is deterministic) for the record, and
/// the run continues through resumeShaftRun.
/// Throws std::invalid_argument on a bad spec.
LatheRunRecord runLatheLoop(LatheRunSpec spec);

/// Per control point: sample variance of the true deviation over parts [from, to] (1-based), mm².
Eigen::VectorXd deviationVariance(const std::vector<Eigen::VectorXd>& perPart, std::int64_t from, std::int64_t to);

/// Mean and standard deviation over parts [from, to] (1-based) of each column, mm.
struct ProfileStatistics {
    Eigen::VectorXd meanMm;
    Eigen::VectorXd stdMm;
};
/// Mean and standard deviation over parts `from` .. `to` (1-based, inclusive) of per-part profiles.
ProfileStatistics profileStatistics(const std::vector<Eigen::VectorXd>& perPart, std::int64_t from, std::int64_t to);

}  // namespace tt::core
