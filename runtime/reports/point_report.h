#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/tolerance.h"
#include "core/ports/adaptation_record.h"
#include "core/quality/point_analysis.h"
#include "core/storage/measurement_query.h"

namespace tt::runtime {

/// Thrown when the caller's progress callback asks to stop a long report.
class ReportCancelled : public std::runtime_error {
public:
    ReportCancelled() : std::runtime_error("the report was cancelled") {}
};

/// Called with (done, total) work steps; returns false to cancel. May be empty.
using ReportProgress = std::function<bool(std::size_t done, std::size_t total)>;

/// Which chart the report draws for each control point.
enum class ReportChart {
    Automatic,      ///< I-MR for subgroups of 1, X-bar-R for n = 2..10, X-bar-s for n = 11..25
    XbarRange,      ///< X-bar-R (n = 2..25)
    XbarStdDev,     ///< X-bar-s (n = 2..25)
    IndividualsMR,  ///< I-MR (subgroup size 1)
};

/// The report's chart choice as the statistics take it: subgroup size 1..25, the chart kind (Automatic picks
/// by the subgroup size: R up to n = 10, s above, as Montgomery 6th ed. section 6.3 recommends), and the
/// phase-I baseline of the first `baselinePoints` chart points (0 = all), held for the rest (phase II).
/// Throws std::invalid_argument naming the value and its limit on a bad combination.
core::PointAnalysisSettings reportSettings(int subgroupSize, ReportChart chart, std::size_t baselinePoints);

/// The readings of one control point, in production order (pointers into the caller's rows).
struct PointRows {
    int pointIndex = 0;  ///< 0-based
    std::vector<const storage::MeasurementRow*> rows;
};

/// The stored readings grouped by control point, ascending point index.
std::vector<PointRows> rowsByPoint(const std::vector<storage::MeasurementRow>& rows);

/// The specification limits of a point: the stored tolerance of its latest reading that has one, the
/// nominal as target; none when no reading has a tolerance.
std::optional<core::SpecLimits> specOf(const PointRows& point);

/// A change of the loop's controller (an adaptation record of a run) placed on a point's control chart.
struct ChartAdaptation {
    std::int64_t runId = 0;
    std::size_t chartPoint = 0;  ///< 0-based chart point (the part's own, or its subgroup's)
    core::AdaptationRecord record;
};

/// The report of one control point: where it is, its tolerance, the verdict counts and core/quality's
/// chart, run rules and capability (analysePoint).
struct PointReport {
    int pointIndex = 0;  ///< 0-based
    double zMm = 0.0;
    double nominalMm = 0.0;
    std::optional<core::SpecLimits> spec;
    core::VerdictCounts verdicts;
    core::MeasuredSeries series;
    std::vector<storage::RunStart> runStarts;  ///< where each run's readings begin in `series`
    core::PointAnalysis analysis;
    std::vector<ChartAdaptation> adaptations;  ///< placeAdaptations: the controller's changes on the chart
};

/// The report of one control point from its readings (storage::queryPointReadings): the specification limits
/// are the stored ones of its latest judged reading with that reading's nominal as target. Throws
/// std::invalid_argument prefixed with "point i: " when the statistics cannot be computed (too few readings for the
/// chart).
PointReport pointReportOf(const storage::PointReadings& readings, const core::PointAnalysisSettings& settings);

/// The report of every control point read (settings.spec is set per point). Calls `progress` after each point;
/// throws ReportCancelled when it returns false; errors as pointReportOf.
std::vector<PointReport> analyseReport(const std::vector<storage::PointReadings>& readings,
                                       const core::PointAnalysisSettings& settings,
                                       const ReportProgress& progress = {});

/// The short name of a chart kind: "X-bar-R", "X-bar-s", "I-MR".
std::string chartKindName(core::ChartKind kind);

}  // namespace tt::runtime
