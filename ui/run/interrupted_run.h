#pragma once

#include <optional>

#include "runtime/run/stored_runs.h"

namespace tt::ui {

struct AppContext;
class MainWindow;

/// The newest run of the context's history when it was interrupted (runtime::findInterruptedRun); none when it
/// ended, has no part, or its stored request cannot be read (the reason goes to the log).
std::optional<runtime::InterruptedRun> findInterruptedRun(AppContext& context);

/// At start (after the log-in and the history check): when the newest run was interrupted, asks through
/// context.prompt whether to continue it; Yes opens the Run page and resumes it there on its machine with its
/// stored request and controller state (the CLI's resume path). Returns whether it was resumed.
bool offerInterruptedRun(AppContext& context, MainWindow& window);

}  // namespace tt::ui
