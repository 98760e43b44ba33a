#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/tolerance.h"
#include "core/storage/database.h"

namespace tt::storage {

/// Which stored readings a report takes (all runs and points when unset).
struct MeasurementFilter {
    std::optional<std::int64_t> runId;
    std::optional<int> pointIndex;  ///< 0-based
    std::optional<std::string> machine;
    std::optional<std::string> fromUtc;  ///< parts stored at or after this ISO 8601 UTC time
    std::optional<std::string> toUtc;    ///< parts stored before this ISO 8601 UTC time
    /// Per point only its newest `lastReadings` readings (after leaving out the newest `skipNewest`), in the
    /// statistics of queryPointReadings (a capability window: the plant overview's last 125 parts and the 125
    /// before); none: all.
    std::optional<std::int64_t> lastReadings;
    std::int64_t skipNewest = 0;
};

/// The SQL condition (on the readings table as `m`) of a plausible reading: a value measured and not refused as
/// implausible or not a number, what a quality report counts.
QString plausibleReadingCondition();

/// One stored reading of one control point of one part, as the reports use it.
struct MeasurementRow {
    std::int64_t runId = 0;
    std::string machine;
    std::int64_t partNumber = 0;
    std::string recordedAt;  ///< when the part was stored, ISO 8601 UTC
    double timeS = 0.0;      ///< when the reading arrived on the loop's clock, s
    int pointIndex = 0;      ///< 0-based
    double zMm = 0.0;
    double nominalMm = 0.0;
    double measuredMm = 0.0;
    bool accepted = false;  ///< used by the controller
    std::optional<core::ToleranceVerdict> verdict;
    std::optional<double> lowerLimitMm;
    std::optional<double> upperLimitMm;
};

/// Where a run's readings begin among a point's readings (they come run after run).
struct RunStart {
    std::int64_t runId = 0;
    std::size_t firstReading = 0;  ///< index into PointReadings::valuesMm
};

/// One control point's plausible readings as its statistics take them (the report of one point over a whole
/// history reads only these): the values in production order (run, then part) and their verdict counts.
struct PointReadings {
    int pointIndex = 0;                  ///< 0-based
    double zMm = 0.0;                    ///< position of the point, of its first reading
    double nominalMm = 0.0;              ///< nominal diameter of its first reading
    std::optional<double> lowerLimitMm;  ///< tolerance of the latest reading that has one (none: no tolerance)
    std::optional<double> upperLimitMm;
    double limitsNominalMm = 0.0;  ///< nominal diameter of that latest reading (the capability's target)
    std::vector<double> valuesMm;
    std::vector<std::int64_t> partNumbers;
    std::vector<double> timesS;       ///< when each reading arrived on the loop's clock, s
    std::vector<RunStart> runStarts;  ///< one per run in the readings, ascending run
    core::VerdictCounts verdicts;     ///< of these readings; readings without a verdict are not counted
};

/// The readings of every chosen control point, in point order: one pass over the covering index of the readings
/// by point (history migration 4) reading only the columns the statistics need, the verdicts as small numbers. The same
/// readings as queryMeasurements (and in the same order within a point). Throws StorageError on failure.
std::vector<PointReadings> queryPointReadings(Database& db, const MeasurementFilter& filter);

/// Per control point aggregates computed in SQL over the plausible readings (the Reports page's overview of all
/// points; cross-checked against the same figures from the raw rows in tests/core/storage/history).
struct PointAggregate {
    int pointIndex = 0;  ///< 0-based
    std::int64_t count = 0;
    double meanMm = 0.0;
    double sigmaOverallMm = 0.0;  ///< sample standard deviation (n - 1), two passes in SQL; 0 for one reading
    double minMm = 0.0;
    double maxMm = 0.0;
    core::VerdictCounts verdicts;
};

/// The aggregates of every chosen control point, in point order. Throws StorageError on failure.
std::vector<PointAggregate> queryPointAggregates(Database& db, const MeasurementFilter& filter);

/// The chosen parts counted by their verdict, the worst verdict of their chosen plausible readings (a part
/// without a judged reading is not counted), in one SQL aggregate. Throws StorageError on failure.
core::VerdictCounts queryPartVerdicts(Database& db, const MeasurementFilter& filter);

/// The plausible readings of the history (a value measured and not refused as implausible or not a number:
/// what a quality report counts; "accepted" is kept), ordered by run, part and point. One query joined in
/// SQL; throws StorageError on failure.
std::vector<MeasurementRow> queryMeasurements(Database& db, const MeasurementFilter& filter);

}  // namespace tt::storage
