#pragma once

#include <QString>
#include <optional>

#include "core/ports/history_store.h"
#include "core/run/shaft_run_builder.h"
#include "ui/run/run_settings.h"

class QWidget;

namespace tt::ui {

struct AppContext;
class MainWindow;

/// What is stored with a run the Run page starts so it can be identified and set up again (the settings
/// JSON: source "gui", preset, controller, delay, seed, EWMA weight, machine).
core::RunDescription storedRunDescription(const RunSettings& settings, const core::ShaftRunPlan& plan);

/// The settings of a stored run set up again on the built-in simulated lathe, from its settings JSON (a run
/// of the Run page, or of `trueturn simulate --db`: its warm-up plus parts are the last part). Throws
/// std::invalid_argument when the run cannot be continued here (the real lathe, damaged settings).
RunSettings settingsOfStoredRun(const core::RunSummary& run);

/// The newest run of the history when it was interrupted (still "running") and has a part to continue
/// from: the run, where it continues, the settings to continue it with.
struct InterruptedRun {
    core::ResumePoint point;
    RunSettings settings;
    qint64 nextPart() const { return point.lastPartNumber + 1; }
};
/// Looks in the context's history; none when the newest run ended, has no part, or cannot be continued here.
std::optional<InterruptedRun> findInterruptedRun(AppContext& context);

/// At start (after the log-in and the history check): when the newest run was interrupted, asks through
/// context.prompt whether to continue it; Yes opens the Run page and resumes it there (the CLI's resume
/// path: its stored settings and controller state). Returns whether it was resumed.
bool offerInterruptedRun(AppContext& context, MainWindow& window);

}  // namespace tt::ui
