#pragma once

#include <QString>
#include <vector>

#include "core/storage/measurement_query.h"
#include "runtime/reports/point_report.h"

namespace tt::runtime {

/// Every reading as CSV, one line each: run, machine, part, time (ISO 8601 UTC), point (1-based), x_mm,
/// nominal_mm, measured_mm, deviation_mm, verdict. Calls `progress` every few thousand rows (cancel:
/// ReportCancelled, the partial file removed); throws std::runtime_error naming the file when it cannot
/// be written.
void writeMeasurementsCsv(const QString& path, const std::vector<storage::MeasurementRow>& rows,
                          const ReportProgress& progress = {});

/// AQDEF (Q-DAS ASCII transfer format, DFQ; one key per line, CR LF, "/i" = characteristic i): K0100 number
/// of characteristics; K1001/K1002 part number and description; per control point K2001/K2002
/// characteristic number and description, K2022 decimal places, K2101 nominal, K2110/K2111 lower/upper
/// specification limit, K2142 unit; then each reading as K0001/i value with K0004/i date/time
/// (DD.MM.YYYY/HH:MM:SS, UTC). Progress, cancel and errors as writeMeasurementsCsv.
void writeMeasurementsDfq(const QString& path, const std::vector<storage::MeasurementRow>& rows,
                          const ReportProgress& progress = {});

}  // namespace tt::runtime
