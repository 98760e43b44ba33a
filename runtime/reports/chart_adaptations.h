#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "core/ports/adaptation_record.h"
#include "core/ports/history_store.h"
#include "runtime/reports/point_report.h"

namespace tt::runtime {

/// The adaptation records of each run, by run id, each run's in the order they happened.
using RunAdaptations = std::map<std::int64_t, std::vector<core::AdaptationRecord>>;

/// The run ids whose readings a report holds (the union over its points, ascending).
std::vector<std::int64_t> reportRuns(const std::vector<storage::PointReadings>& points);

/// The adaptation records of every run whose readings are in `readings`, from `store`. Throws as the store does
/// (a damaged record: storage::StorageError).
RunAdaptations readRunAdaptations(core::HistoryStore& store, const std::vector<storage::PointReadings>& readings);

/// Places on every point's chart the records of `byRun` that changed the controller (applied): at the chart point
/// of the first reading of that run at or after the record's part. A record after its run's last reading, or in
/// the incomplete last subgroup the chart leaves out, is not placed. Replaces any earlier placement.
void placeAdaptations(std::vector<PointReport>& points, const RunAdaptations& byRun);

}  // namespace tt::runtime
