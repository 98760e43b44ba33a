#pragma once

#include <QString>

#include "core/control/run_to_run_setup.h"
#include "ui/app_context.h"

namespace tt::ui {

/// What changed between two run-to-run setups, one clause per changed value ("delay z 4 -> 3",
/// "point 2 R2 0.01 -> 0.02"), in English for the record; empty when nothing changed.
QString describeTuningChange(const core::RunToRunSetup& before, const core::RunToRunSetup& after);

/// Records that the user in `context` applied `after` in place of `before`: one audit-trail row per changed
/// value (category "controller", who, when, old and new) and a line in the log (trueturn.loop). Returns the
/// log line's text.
QString recordTuningChange(AppContext& context, const core::RunToRunSetup& before, const core::RunToRunSetup& after);

}  // namespace tt::ui
