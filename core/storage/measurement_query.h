#pragma once

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
};

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

/// The plausible readings of the history (a value measured and not refused as implausible or not a number:
/// what a quality report counts; "accepted" is kept), ordered by run, part and point. One query joined in
/// SQL; throws StorageError on failure.
std::vector<MeasurementRow> queryMeasurements(Database& db, const MeasurementFilter& filter);

}  // namespace tt::storage
