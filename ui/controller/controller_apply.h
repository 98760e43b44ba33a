#pragma once

#include <QString>

#include "core/control/run_to_run_setup.h"
#include "ui/app_context.h"

namespace tt::ui {

/// What changed between two run-to-run setups, one clause per changed value ("delay z 4 -> 3",
/// "point 2 R2 0.01 -> 0.02"), in English for the record; empty when nothing changed.
QString describeTuningChange(const core::RunToRunSetup& before, const core::RunToRunSetup& after);

/// Records that the operator in `context` applied `after` in place of `before` (who, what). Today it writes
/// the record to the log (category trueturn.loop); the audit trail takes it over at integration. Returns
/// the record's text.
QString recordTuningChange(AppContext& context, const core::RunToRunSetup& before, const core::RunToRunSetup& after);

}  // namespace tt::ui
