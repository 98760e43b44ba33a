#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/control/disturbance_identification.h"
#include "core/storage/database.h"

namespace tt::ui {

/// The disturbance of every control point of one stored run, fitted as ARMA(1, 1) (issue 13 item 5):
/// what the Controller page's "Identify from history" shows and turns into the typed shaping filter.
struct HistoryIdentification {
    std::vector<core::DisturbanceIdentification> points;  ///< point 0, 1, ... that could be fitted
    QString problem;  ///< why nothing could be fitted at point 1 (no run, too few parts), the engine's words
};

/// Opens its own connection to `config` (the calling thread's; QtSql connections do not cross threads)
/// and fits points 0 .. pointCount - 1 of run `runId` (none: the newest) with k_i = `gainPerPoint`
/// (diameter per radial move). A point that cannot be fitted after point 1 is left out; a failure at
/// point 1 or of the database is returned in `problem`. Meant for a worker thread.
HistoryIdentification identifyFromHistory(const storage::DatabaseConfig& config, std::optional<std::int64_t> runId,
                                          const std::vector<double>& gainPerPoint);

}  // namespace tt::ui
