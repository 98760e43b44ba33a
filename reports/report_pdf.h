#pragma once

#include <QCoreApplication>
#include <QString>
#include <vector>

#include "core/ports/history_store.h"
#include "core/storage/measurement_query.h"
#include "runtime/reports/point_report.h"

namespace tt::reports {

/// The title block of a report: what was chosen and where the readings come from.
struct ReportHeader {
    QString machines;   ///< the machines of the readings, comma separated ("-" when untagged)
    QString jobs;       ///< the presets (jobs) of the runs, preset files by their file name
    QString runs;       ///< "3, 4, 7"
    QString dateRange;  ///< first .. last stored part, UTC
    std::int64_t parts = 0;
};

/// The title block of `rows`, the jobs named from the stored run summaries.
ReportHeader reportHeaderOf(const std::vector<storage::MeasurementRow>& rows,
                            const std::vector<core::RunSummary>& runs);

/// The quality report as a PDF (A4, vector charts): a title page with the title block, the summary of every
/// point, all points' location charts side by side and a signature line; then one page per control point
/// with its control charts, histogram, capability table, rule violations and verdicts. Needs a
/// QApplication (the charts are widgets; the command line makes one on the offscreen platform). Calls
/// `progress` per page (cancel: runtime::ReportCancelled, no file left); throws std::runtime_error naming the file
/// when it cannot be written.
class ReportPdf {
    Q_DECLARE_TR_FUNCTIONS(tt::reports::ReportPdf)
public:
    static void write(const QString& path, const ReportHeader& header, const std::vector<runtime::PointReport>& points,
                      const runtime::ReportProgress& progress = {});

private:
    class Sheet;
    struct PointCharts;
    /// The title block, the summary line of every point, the points' location charts side by side and
    /// the signature line.
    static void writeTitlePage(Sheet& sheet, const ReportHeader& header,
                               const std::vector<runtime::PointReport>& points);
    /// The points' location charts in rows of three, as many as fit above the signature line, then the line.
    static void writeSmallMultiples(Sheet& sheet, const std::vector<runtime::PointReport>& points);
    /// A control point's page: its control charts, histogram, capability table and rule violations.
    static void writePointPage(Sheet& sheet, const ReportHeader& header, const runtime::PointReport& p,
                               PointCharts& charts);
};

}  // namespace tt::reports
