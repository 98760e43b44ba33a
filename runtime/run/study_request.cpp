#include "runtime/run/study_request.h"

#include "core/run/shaft_run_builder.h"
#include "runtime/run/stored_runs.h"

namespace tt::runtime {

core::LatheStudyOptions studyOptionsOf(const RunRequest& request, const config::LoopScenario& scenario) {
    if (!request.endPart) throw RunRequestError("end_part", "a headless run needs its last part");
    core::LatheStudyOptions options;
    options.controller = request.controller;
    options.ewmaWeight = request.ewmaWeight;
    options.parts = *request.endPart - request.warmupParts;
    options.warmupParts = request.warmupParts;
    options.speed = request.speed;
    options.description = storedRunDescription(request, core::planShaftRun(scenario, choiceOf(request)));
    return options;
}

}  // namespace tt::runtime
