#include "runtime/reports/point_report.h"

#include <map>

namespace tt::runtime {

core::PointAnalysisSettings reportSettings(int subgroupSize, ReportChart chart, std::size_t baselinePoints) {
    if (subgroupSize < 1 || subgroupSize > 25)
        throw std::invalid_argument("the subgroup size " + std::to_string(subgroupSize) + " is outside 1..25");
    core::PointAnalysisSettings settings;
    switch (chart) {
        case ReportChart::Automatic:
            settings.spread = subgroupSize > 10 ? core::SubgroupSpread::StdDev : core::SubgroupSpread::Range;
            break;
        case ReportChart::IndividualsMR:
            if (subgroupSize != 1)
                throw std::invalid_argument("the I-MR chart plots single parts: the subgroup size must be 1, not " +
                                            std::to_string(subgroupSize));
            break;
        case ReportChart::XbarRange:
        case ReportChart::XbarStdDev:
            if (subgroupSize < 2)
                throw std::invalid_argument("an X-bar chart needs subgroups of 2..25 parts, not " +
                                            std::to_string(subgroupSize));
            settings.spread =
                chart == ReportChart::XbarStdDev ? core::SubgroupSpread::StdDev : core::SubgroupSpread::Range;
            break;
    }
    settings.subgroupSize = subgroupSize;
    settings.baseline = core::ChartBaseline{0, baselinePoints};
    return settings;
}

std::vector<PointRows> rowsByPoint(const std::vector<storage::MeasurementRow>& rows) {
    std::map<int, PointRows> points;
    for (const storage::MeasurementRow& row : rows) {
        PointRows& p = points[row.pointIndex];
        p.pointIndex = row.pointIndex;
        p.rows.push_back(&row);
    }
    std::vector<PointRows> out;
    out.reserve(points.size());
    for (auto& [index, point] : points)
        out.push_back(std::move(point));
    return out;
}

std::optional<core::SpecLimits> specOf(const PointRows& point) {
    for (auto it = point.rows.rbegin(); it != point.rows.rend(); ++it)
        if ((*it)->lowerLimitMm && (*it)->upperLimitMm)
            return core::SpecLimits{*(*it)->lowerLimitMm, *(*it)->upperLimitMm, (*it)->nominalMm};
    return std::nullopt;
}

PointReport pointReportOf(const storage::PointReadings& readings, const core::PointAnalysisSettings& settings) {
    PointReport report;
    report.pointIndex = readings.pointIndex;
    report.zMm = readings.zMm;
    report.nominalMm = readings.nominalMm;
    if (readings.lowerLimitMm && readings.upperLimitMm)
        report.spec = core::SpecLimits{*readings.lowerLimitMm, *readings.upperLimitMm, readings.limitsNominalMm};
    report.verdicts = readings.verdicts;
    report.series.valuesMm = readings.valuesMm;
    report.series.partNumbers = readings.partNumbers;
    report.series.timesS = readings.timesS;
    report.runStarts = readings.runStarts;
    core::PointAnalysisSettings pointSettings = settings;
    pointSettings.spec = report.spec;
    try {
        report.analysis = core::analysePoint(report.series, pointSettings);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("point " + std::to_string(readings.pointIndex + 1) + ": " + e.what());
    }
    return report;
}

std::vector<PointReport> analyseReport(const std::vector<storage::PointReadings>& readings,
                                       const core::PointAnalysisSettings& settings, const ReportProgress& progress) {
    std::vector<PointReport> reports;
    reports.reserve(readings.size());
    for (const storage::PointReadings& point : readings) {
        if (progress && !progress(reports.size(), readings.size())) throw ReportCancelled();
        reports.push_back(pointReportOf(point, settings));
    }
    if (progress && !progress(reports.size(), readings.size())) throw ReportCancelled();
    return reports;
}

std::string chartKindName(core::ChartKind kind) {
    switch (kind) {
        case core::ChartKind::XbarRange:
            return "X-bar-R";
        case core::ChartKind::XbarStdDev:
            return "X-bar-s";
        case core::ChartKind::IndividualsMovingRange:
            break;
    }
    return "I-MR";
}

}  // namespace tt::runtime
