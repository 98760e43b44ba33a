#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>

#include "core/control/run_to_run_plant.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_config.h"
#include "core/loop/loop_engine.h"
#include "core/ports/history_store.h"
#include "core/ports/shaft_machine.h"
#include "core/run/shaft_scenario.h"

namespace tt::core {

/// The choices made for one shaft run (on the Run page, on the command line, or stored with the run).
struct ShaftRunChoice {
    ControllerKind controller = ControllerKind::Lqg;
    /// EWMA lambda in (0, 1]; none: the scenario's, or the best on the grid when it says auto.
    std::optional<double> ewmaWeight;
    /// The run ends after this part; none: until stopped.
    std::optional<std::int64_t> lastPartNumber;
};

/// A shaft run planned from its scenario and choices: the loop's settings (with the feed-forward of the
/// systematic model unless the loop is open), the controller's plant, kind and EWMA weight.
struct ShaftRunPlan {
    LoopConfig loop;
    RunToRunPlant plant;
    ControllerKind controller = ControllerKind::Lqg;
    double ewmaWeight = 0.0;  ///< the lambda an EWMA controller uses
};

/// The CNC output is set up for another diameter than the scenario turns (a G-code file output writes
/// programs for one nominal diameter): the run is refused.
class OutputDiameterMismatch : public std::invalid_argument {
public:
    OutputDiameterMismatch(double outputMm, double scenarioMm);
    double outputMm;    ///< the diameter the output writes programs for
    double scenarioMm;  ///< the scenario's nominal diameter
};

/// Plans a run. Throws std::invalid_argument on a bad scenario or choice (the reason).
ShaftRunPlan planShaftRun(const ShaftScenario& scenario, const ShaftRunChoice& choice);

/// A fresh controller of the plan's kind for its plant (LQG designed with the scenario's weights).
std::unique_ptr<RunToRunController> makeShaftController(const ShaftScenario& scenario, const ShaftRunPlan& plan);

/// The one place a shaft run is assembled, for the GUI, the CLI and the tests: the loop engine with a
/// fresh controller on the machine's ports (part cycle, CNC output, gauge, clock) and the history
/// (may be null: nothing stored), ready to start() or to resume with resumeShaftRun(). `gauge`
/// replaces the machine's gauge when given (diameters typed by hand through a SelectableGauge).
/// Throws OutputDiameterMismatch, or std::invalid_argument on a bad plan.
std::unique_ptr<LoopEngine> buildShaftRun(const ShaftScenario& scenario, const ShaftRunPlan& plan,
                                          ShaftMachine& machine, HistoryStore* history, DiameterGauge* gauge = nullptr);

/// The scenario with the controller tuning the commissioning engineer applied (the Controller page): its LQG
/// weights R1 / R2, the controller's correction limits, the LQG and EWMA options (the run's EWMA weight
/// stays), the integral action and each control point's disturbance model; the plant itself (points, gains,
/// delay z) and the loop's own limits stay the scenario's. Throws std::invalid_argument when the tuning has
/// another number of control points than the scenario.
ShaftScenario withControllerTuning(ShaftScenario scenario, const RunToRunSetup& tuning);

/// A controller of the running plan's kind designed with `tuning` (withControllerTuning), for
/// LoopEngine::replaceController. Throws std::invalid_argument as withControllerTuning and planShaftRun.
std::unique_ptr<RunToRunController> retunedShaftController(const ShaftScenario& scenario, const ShaftRunPlan& plan,
                                                           const RunToRunSetup& tuning);

/// Resume on a simulated machine: every stored part of the run is machined again (ShaftMachine::replayPart) so
/// its process continues where it stopped; nothing happens on a real machine.
void replayStoredParts(ShaftMachine& machine, const LoopConfig& loop, const std::vector<StoredPart>& parts);

/// Continues a stored run on the machine: its parts machined but not measured go back on the
/// measuring station (ShaftMachine::restorePart), then the engine resumes from the stored state.
void resumeShaftRun(LoopEngine& engine, ShaftMachine& machine, const LoopConfig& loop, const ResumePoint& point);

}  // namespace tt::core
