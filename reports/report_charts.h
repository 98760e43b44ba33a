#pragma once

#include <QCoreApplication>
#include <QString>
#include <cstdint>
#include <vector>

#include "core/storage/measurement_query.h"
#include "runtime/reports/point_report.h"

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::reports {

/// A histogram of the readings of one point: equal bins over the readings and the specification limits.
struct ReportHistogram {
    double firstEdgeMm = 0.0;
    double binWidthMm = 0.0;
    std::vector<double> centresMm;
    std::vector<double> counts;
};

/// sqrt(n) bins (5..30) spanning the readings and, when given, the specification limits.
ReportHistogram histogramOf(const runtime::PointReport& point);

/// One line of the capability table: the index, its value and its 95 % interval (empty when none).
struct CapabilityLine {
    QString name;
    QString value;
    QString interval;
};

/// The measured diameters of one part along the shaft with the tolerance band of each point.
struct PartProfile {
    std::vector<double> zMm;
    std::vector<double> measuredMm;
    std::vector<double> lowerMm;  ///< tolerance band (nominal where no tolerance is stored)
    std::vector<double> upperMm;
    std::vector<double> nominalMm;
};

/// A series as drawn: its x and y.
struct ChartSeries {
    std::vector<double> xs;
    std::vector<double> ys;
};

/// The points of a series drawn `columns` pixel columns wide: per column (an equal share of the x range) its lowest
/// and its highest point, in their order, so every excursion stays visible (the envelope of the drawn line is the
/// full series'); a series of at most 2 × `columns` points, or `columns` < 1, unchanged. `xs` ascending.
ChartSeries decimateMinMax(const std::vector<double>& xs, const std::vector<double>& ys, int columns);

/// The readings of part `partNumber` of run `runId` along the shaft, ascending x.
PartProfile partProfileOf(const std::vector<storage::MeasurementRow>& rows, std::int64_t runId,
                          std::int64_t partNumber);

/// The charts and tables of the quality report, drawn the same on the Reports page and in the PDF (every
/// statistic comes from the runtime::PointReport: core/quality's analysePoint).
class ReportCharts {
    Q_DECLARE_TR_FUNCTIONS(tt::reports::ReportCharts)
public:
    /// The location chart (X-bar or individuals) with centre line, control limits and the chart points of
    /// rule violations marked; `compact` for a small multiple (titled with the point, no legend).
    /// `columns` > 0: the series decimated to that many pixel columns (decimateMinMax; the printed report).
    static void showLocation(plot::Chart& chart, const runtime::PointReport& point, bool compact = false,
                             int columns = 0);
    /// The spread chart (R, s or moving range) with its centre line and limits; `columns` as for showLocation.
    static void showSpread(plot::Chart& chart, const runtime::PointReport& point, int columns = 0);
    /// The histogram with the specification limits, the nominal and the fitted normal density (mean and
    /// overall sigma) scaled to counts.
    static void showHistogram(plot::Chart& chart, const runtime::PointReport& point);
    /// One part's diameters along the shaft inside the tolerance band.
    static void showProfile(plot::Chart& chart, const PartProfile& profile, const QString& title);
    /// Cp, Cpk, Cpm, Pp, Ppk with their intervals, then the method, the normality p, sigma within and overall.
    static std::vector<CapabilityLine> capabilityLines(const runtime::PointReport& point);
    /// A controller change in a few words: "LQG adapted, delay z = 2" (to the plant identified from the run).
    static QString adaptationText(const core::AdaptationRecord& record);
    /// One line per controller change on the point's chart ("Run 3, part 154: …"), at most `maxLines` and a last
    /// line saying how many more.
    static QStringList adaptationLines(const runtime::PointReport& point, int maxLines);
    /// "Point 3 at x = 120.0 mm".
    static QString pointTitle(const runtime::PointReport& point);
    /// "X-bar-R chart of subgroups of 5, limits from 20 subgroups".
    static QString chartDescription(const runtime::PointReport& point);
    /// "good 120 · rework 20 · scrap 10".
    static QString verdictText(const core::VerdictCounts& verdicts);
    /// The rule violations, one per line: "WE1: parts 12, 13"; at most `maxLines`, then "... and n more".
    static QStringList violationLines(const runtime::PointReport& point, int maxLines);
};

}  // namespace tt::reports
