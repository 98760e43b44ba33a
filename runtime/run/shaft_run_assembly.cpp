#include "runtime/run/shaft_run_assembly.h"

#include "runtime/run/stored_runs.h"

namespace tt::runtime {

std::unique_ptr<AssembledRun> assembleRun(const RunRequest& request, const MachineMaker& make,
                                          core::HistoryStore* history) {
    validate(request);
    auto run = std::make_unique<AssembledRun>();
    run->request = request;
    run->scenario = scenarioOf(request);
    run->plan = core::planShaftRun(run->scenario, choiceOf(request));
    run->machine = make(run->scenario);
    run->machine->setManualEntry(request.manualEntry);
    run->gauge = std::make_unique<core::SelectableGauge>(run->machine->gauge(), run->manual);
    run->gauge->setManual(request.manualEntry);
    run->engine = core::buildShaftRun(run->scenario, run->plan, *run->machine, history, run->gauge.get());
    run->stepper = std::make_unique<core::ShaftRunStepper>(*run->engine, *run->machine);
    return run;
}

void startRun(AssembledRun& run) {
    run.engine->start(storedRunDescription(run.request, run.plan));
}

void resumeRun(AssembledRun& run, const core::ResumePoint& point, const std::vector<core::StoredPart>& storedParts) {
    core::replayStoredParts(*run.machine, run.plan.loop, storedParts);
    core::resumeShaftRun(*run.engine, *run.machine, run.plan.loop, point);
}

}  // namespace tt::runtime
