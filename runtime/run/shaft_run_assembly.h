#pragma once

#include <memory>
#include <optional>

#include "config/loop_scenario.h"
#include "core/loop/loop_engine.h"
#include "core/loop/manual_gauge.h"
#include "core/loop/shaft_run_stepper.h"
#include "core/ports/history_store.h"
#include "core/run/shaft_run_builder.h"
#include "runtime/run/machine_catalog.h"
#include "runtime/run/run_request.h"

namespace tt::runtime {

/// Everything one shaft run is made of once its request is assembled, in the order it must be built and
/// torn down: the scenario and plan of the request (scenarioOf, planShaftRun), the machine, the gauge the
/// loop reads (the machine's, or the diameters typed by hand), the engine the run builder made on them
/// (core::buildShaftRun) and the stepper that drives it (core::ShaftRunStepper). The loop thread owns it;
/// the GUI never touches it.
struct AssembledRun {
    RunRequest request;
    config::LoopScenario scenario;
    core::ShaftRunPlan plan;
    std::shared_ptr<core::ShaftMachine> machine;
    core::ManualGauge manual;
    std::unique_ptr<core::SelectableGauge> gauge;
    std::unique_ptr<core::LoopEngine> engine;
    std::unique_ptr<core::ShaftRunStepper> stepper;
};

/// Assembles a run of `request` on the machine `make` makes (called here, in the calling thread), storing in
/// `history` (may be null). Throws RunRequestError for a bad request, core::OutputDiameterMismatch when the
/// CNC output is set up for another diameter, std::invalid_argument otherwise.
std::unique_ptr<AssembledRun> assembleRun(const RunRequest& request, const MachineMaker& make,
                                          core::HistoryStore* history);

/// Starts the assembled run (stored with its request when there is a history).
void startRun(AssembledRun& run);

/// Continues the stored run `point` on the assembled run: a simulated machine machines the stored parts
/// again (core::replayStoredParts), the parts waiting for the gauge go back on the rack and the engine
/// resumes from the stored controller state (core::resumeShaftRun).
void resumeRun(AssembledRun& run, const core::ResumePoint& point, const std::vector<core::StoredPart>& storedParts);

}  // namespace tt::runtime
