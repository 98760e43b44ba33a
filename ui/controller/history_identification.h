#pragma once

#include <QString>
#include <cstdint>
#include <optional>

#include "core/control/run_to_run_setup.h"
#include "core/run/stored_run_tuning.h"
#include "core/storage/database.h"

namespace tt::ui {

/// The plant of one stored run identified at every control point and the LQG designed for it (the commissioning
/// step of `trueturn tune`, core::tuneFromStoredRun): what the Controller page's "Identify from history" shows and
/// designs with.
struct HistoryIdentification {
    std::optional<core::StoredRunTuning> tuning;  ///< none when nothing could be identified
    QString problem;  ///< why not (no run, too few parts: how many more), the engine's words
};

/// Opens its own connection to `config` (the calling thread's; QtSql connections do not cross threads), identifies
/// run `runId` (none: the newest) with its own delay z for the controller's `setup` (its model as the start) and
/// designs for it. Meant for a worker thread.
HistoryIdentification identifyFromHistory(const storage::DatabaseConfig& config, std::optional<std::int64_t> runId,
                                          const core::RunToRunSetup& setup);

}  // namespace tt::ui
