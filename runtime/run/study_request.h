#pragma once

#include "config/loop_scenario.h"
#include "core/run/shaft_study.h"
#include "runtime/run/run_request.h"

namespace tt::runtime {

/// What a headless study (`trueturn simulate`, core::runLatheStudy) takes from a run request and its scenario
/// (scenarioOf): the controller and its EWMA weight, the parts counted (end part minus warm-up) and the
/// warm-up, the pace, and the description stored with the run (storedRunDescription: the request itself).
/// Throws RunRequestError("end_part", ...) when the request has no end: a headless run needs its last part.
core::LatheStudyOptions studyOptionsOf(const RunRequest& request, const config::LoopScenario& scenario);

}  // namespace tt::runtime
