#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/tolerance.h"
#include "core/storage/database.h"
#include "core/storage/measurement_query.h"

namespace tt::storage {

/// What the plant overview reads.
struct PlantQuery {
    std::string dayFromUtc;  ///< the day's parts: stored at or after this ISO 8601 UTC time ...
    std::string dayToUtc;    ///< ... and before this one
    int windowParts = 125;   ///< readings per point in a capability window; the newest 2 windows are read
};

/// What a terminal last reported about itself (plant_terminal_status).
struct TerminalReportRow {
    std::string reportedAt;  ///< ISO 8601 UTC
    std::int64_t backlogParts = 0;
    std::int64_t journalBytes = 0;
    std::int64_t journalLimitBytes = 0;
};

/// An alarm of a machine's current run.
struct PlantAlarm {
    std::int64_t runId = 0;
    std::optional<std::int64_t> partNumber;
    std::string kind;
    std::string message;
    std::string recordedAt;  ///< ISO 8601 UTC
};

/// One machine of the plant database as the overview reads it.
struct PlantMachineRow {
    std::string machine;
    std::optional<std::int64_t> newestRunId;
    std::string newestRunStatus;       ///< "running", "complete", "stopped", "fault" (latest end of the newest run)
    bool newestRunOpen = false;        ///< the newest run has not ended
    std::optional<std::string> lastPartAt;  ///< when its newest part was stored, ISO 8601 UTC
    std::optional<TerminalReportRow> terminal;  ///< none: it writes without a journal (or never reported)
    core::VerdictCounts dayParts;      ///< the day's parts by their verdict (the worst of their points)
    std::int64_t dayPartCount = 0;     ///< the day's parts, with or without a verdict
    /// Per control point (ascending) its newest plausible readings, at most 2 × windowParts, in production order
    /// (run, part), with the tolerance of the newest judged one (as queryPointReadings).
    std::vector<PointReadings> recent;
    std::int64_t openAlarmCount = 0;   ///< alarms of the newest run while it has not ended
    std::vector<PlantAlarm> openAlarms;  ///< the newest of them (at most 5), newest first
};

/// Every machine of the plant database (every machine named by a run or a terminal's report), by name. A few
/// short queries per machine over the indexes of history migration 5 (runs by machine, parts by run and time),
/// so the cost grows with the machines, not with the parts stored. Throws StorageError.
std::vector<PlantMachineRow> queryPlant(Database& db, const PlantQuery& query);

}  // namespace tt::storage
