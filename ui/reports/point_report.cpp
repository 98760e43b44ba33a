#include "ui/reports/point_report.h"

#include <map>

namespace tt::ui {

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

core::MeasuredSeries seriesOf(const PointRows& point) {
    core::MeasuredSeries series;
    series.valuesMm.reserve(point.rows.size());
    series.partNumbers.reserve(point.rows.size());
    series.timesS.reserve(point.rows.size());
    for (const storage::MeasurementRow* row : point.rows) {
        series.valuesMm.push_back(row->measuredMm);
        series.partNumbers.push_back(row->partNumber);
        series.timesS.push_back(row->timeS);
    }
    return series;
}

core::VerdictCounts verdictsOf(const PointRows& point) {
    core::VerdictCounts counts;
    for (const storage::MeasurementRow* row : point.rows)
        if (row->verdict) counts.add(*row->verdict);
    return counts;
}

std::vector<PointReport> analyseReport(const std::vector<storage::MeasurementRow>& rows,
                                       const core::PointAnalysisSettings& settings, const ReportProgress& progress) {
    const std::vector<PointRows> points = rowsByPoint(rows);
    std::vector<PointReport> reports;
    reports.reserve(points.size());
    for (const PointRows& point : points) {
        if (progress && !progress(reports.size(), points.size())) throw ReportCancelled();
        PointReport report;
        report.pointIndex = point.pointIndex;
        report.zMm = point.rows.front()->zMm;
        report.nominalMm = point.rows.front()->nominalMm;
        report.spec = specOf(point);
        report.verdicts = verdictsOf(point);
        report.series = seriesOf(point);
        core::PointAnalysisSettings pointSettings = settings;
        pointSettings.spec = report.spec;
        try {
            report.analysis = core::analysePoint(report.series, pointSettings);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("point " + std::to_string(point.pointIndex + 1) + ": " + e.what());
        }
        reports.push_back(std::move(report));
    }
    if (progress && !progress(reports.size(), points.size())) throw ReportCancelled();
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

}  // namespace tt::ui
