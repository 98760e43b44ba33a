#pragma once

#include <optional>

#include "core/ports/history_store.h"
#include "core/run/shaft_run_builder.h"
#include "core/run/shaft_scenario.h"
#include "runtime/run/run_request.h"

namespace tt::runtime {

/// What is stored with a run so it can be identified and set up again: the preset, controller, delay and
/// control points of its plan, the lathe's name, and the run request itself as the settings JSON
/// ({"source": "request", "request": {...}}; the database is where it is stored, so it is left out).
core::RunDescription storedRunDescription(const RunRequest& request, const core::ShaftRunPlan& plan);

/// The run request stored with `run` (the request format, and the two older formats: a run of the Run page,
/// source "gui", and of `trueturn simulate --db`, source "simulate", whose warm-up plus parts are its last
/// part). Throws RunRequestError naming run and field when the settings are damaged or from elsewhere.
RunRequest requestOfStoredRun(const core::RunSummary& run);

/// The newest run of a history when it was interrupted (still "running") and has a part to continue from.
struct InterruptedRun {
    core::ResumePoint point;
    RunRequest request;  ///< the request to continue it with (requestOfStoredRun)
    std::int64_t nextPart() const { return point.lastPartNumber + 1; }
};

/// The newest run of `history` when it was interrupted; none when it ended, has no part, or its settings
/// cannot be read (the reason is thrown as RunRequestError so the caller can log it).
std::optional<InterruptedRun> findInterruptedRun(core::HistoryStore& history);

}  // namespace tt::runtime
