#include "reports/report_pdf.h"

#include <qcustomplot.h>

#include <QDateTime>
#include <QFileInfo>
#include <QPageLayout>
#include <QPdfWriter>
#include <QSaveFile>
#include <algorithm>
#include <memory>
#include <set>
#include <stdexcept>

#include "plot/chart.h"
#include "reports/report_charts.h"

namespace tt::reports {

namespace {

/// Logical units of the PDF pages: 96 per inch, so the charts are laid out as on a screen. A chart's series are
/// decimated to its width in these units (a printed pixel column each, keeping its lowest and highest point).
constexpr int kDpi = 96;
constexpr int kChartFontPt = 8;
constexpr int kSmallMultiplesPerRow = 3;

std::unique_ptr<plot::Chart> printChart() {
    auto chart = std::make_unique<plot::Chart>();
    chart->setAttribute(Qt::WA_DontShowOnScreen);
    chart->setMinimumHeight(0);
    chart->setFontPointSize(kChartFontPt);
    return chart;
}

}  // namespace

/// Text and charts laid out top to bottom on the current page.
class ReportPdf::Sheet {
public:
    Sheet(QPdfWriter& writer, QCPPainter& painter) : m_writer(writer), m_painter(painter) {
        m_width = painter.viewport().width();
        m_height = painter.viewport().height();
    }

    int width() const { return m_width; }
    int remaining() const { return m_height - m_y; }

    void newPage() {
        m_writer.newPage();
        m_y = 0;
    }

    /// A line of text at `pointSize`, bold when asked; returns its height.
    void text(const QString& line, int pointSize, bool bold = false, int indent = 0) {
        QFont f(QStringLiteral("DejaVu Sans"), pointSize);
        f.setBold(bold);
        m_painter.setFont(f);
        const QFontMetrics metrics(f, &m_writer);
        const QRect box(indent, m_y, m_width - indent, metrics.height());
        m_painter.setPen(Qt::black);
        m_painter.drawText(box, Qt::AlignLeft | Qt::AlignVCenter,
                           metrics.elidedText(line, Qt::ElideRight, box.width()));
        m_y += metrics.height() + 2;
    }

    /// Rows of (label, value, interval) in three columns starting at x = `left`, `columnWidth` wide.
    void table(const std::vector<CapabilityLine>& lines, int left, int top, int columnWidth) {
        QFont f(QStringLiteral("DejaVu Sans"), 9);
        const QFontMetrics metrics(f, &m_writer);
        const int rowHeight = metrics.height() + 4;
        int y = top;
        m_painter.setPen(QPen(Qt::gray, 0.5));
        for (const CapabilityLine& line : lines) {
            const int c0 = columnWidth * 46 / 100, c1 = columnWidth * 18 / 100, c2 = columnWidth - c0 - c1;
            m_painter.setFont(f);
            m_painter.setPen(Qt::black);
            m_painter.drawText(QRect(left, y, c0, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                               metrics.elidedText(line.name, Qt::ElideRight, c0 - 4));
            if (line.interval.isEmpty()) {  // a value without interval (the method) takes both columns
                m_painter.drawText(QRect(left + c0, y, c1 + c2, rowHeight), Qt::AlignRight | Qt::AlignVCenter,
                                   metrics.elidedText(line.value, Qt::ElideRight, c1 + c2));
            } else {
                m_painter.drawText(QRect(left + c0, y, c1, rowHeight), Qt::AlignRight | Qt::AlignVCenter, line.value);
                m_painter.drawText(QRect(left + c0 + c1, y, c2, rowHeight), Qt::AlignRight | Qt::AlignVCenter,
                                   QStringLiteral("(%1)").arg(line.interval));
            }
            m_painter.setPen(QPen(Qt::lightGray, 0.5));
            m_painter.drawLine(QLineF(left, y + rowHeight, left + columnWidth, y + rowHeight));
            y += rowHeight;
        }
    }

    /// The chart in a box `height` high at the cursor (full width) or at `box`.
    void chart(plot::Chart& chart, const QRect& box) {
        chart.resize(box.size());
        chart.render(m_painter, box);
    }
    QRect take(int height) {
        const QRect box(0, m_y, m_width, height);
        m_y += height + 6;
        return box;
    }
    void skip(int pixels) { m_y += pixels; }
    int y() const { return m_y; }

    void rule() {
        m_painter.setPen(QPen(Qt::darkGray, 1.0));
        m_painter.drawLine(QLineF(0, m_y, m_width, m_y));
        m_y += 6;
    }

private:
    QPdfWriter& m_writer;
    QCPPainter& m_painter;
    int m_width = 0;
    int m_height = 0;
    int m_y = 0;
};

ReportHeader reportHeaderOf(const std::vector<storage::MeasurementRow>& rows,
                            const std::vector<core::RunSummary>& runs) {
    ReportHeader h;
    std::set<std::string> machines;
    std::set<std::int64_t> runIds;
    std::set<std::pair<std::int64_t, std::int64_t>> parts;
    std::string first, last;
    for (const storage::MeasurementRow& r : rows) {
        machines.insert(r.machine.empty() ? "-" : r.machine);
        runIds.insert(r.runId);
        parts.insert({r.runId, r.partNumber});
        if (first.empty() || r.recordedAt < first) first = r.recordedAt;
        if (last.empty() || r.recordedAt > last) last = r.recordedAt;
    }
    QStringList m, j, n;
    for (const std::string& s : machines)
        m << QString::fromStdString(s);
    std::set<std::string> jobs;
    for (const core::RunSummary& run : runs)
        if (runIds.count(run.runId)) jobs.insert(run.description.preset);
    for (const std::string& s : jobs)  // a preset file by its name, a built-in preset as it is
        j << QFileInfo(QString::fromStdString(s)).fileName();
    for (const std::int64_t id : runIds)
        n << QString::number(id);
    h.machines = m.join(QStringLiteral(", "));
    h.jobs = j.join(QStringLiteral(", "));
    h.runs = n.join(QStringLiteral(", "));
    const auto day = [](const std::string& iso) {
        const QDateTime t = QDateTime::fromString(QString::fromStdString(iso), Qt::ISODateWithMs);
        return t.isValid() ? t.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm")) : QString::fromStdString(iso);
    };
    h.dateRange = rows.empty() ? QString() : QStringLiteral("%1 … %2 UTC").arg(day(first), day(last));
    h.parts = static_cast<std::int64_t>(parts.size());
    return h;
}

/// The charts of a point's page, made once and drawn again for every point.
struct ReportPdf::PointCharts {
    std::unique_ptr<plot::Chart> location = printChart();
    std::unique_ptr<plot::Chart> spread = printChart();
    std::unique_ptr<plot::Chart> histogram = printChart();
};

void ReportPdf::write(const QString& path, const ReportHeader& header, const std::vector<runtime::PointReport>& points,
                      const runtime::ReportProgress& progress) {
    if (points.empty()) throw std::invalid_argument("a PDF report needs at least one control point");
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw std::runtime_error("cannot write '" + path.toStdString() + "': " + file.errorString().toStdString());
    const std::size_t pages = points.size() + 1;
    {
        QPdfWriter writer(&file);
        writer.setTitle(tr("Quality report"));
        writer.setCreator(QStringLiteral("TrueTurn"));
        writer.setResolution(kDpi);
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(15, 12, 15, 12),
                                         QPageLayout::Millimeter));
        QCPPainter painter(&writer);
        painter.setMode(QCPPainter::pmVectorized);
        painter.setMode(QCPPainter::pmNoCaching);
        Sheet sheet(writer, painter);
        if (progress && !progress(0, pages)) throw runtime::ReportCancelled();
        writeTitlePage(sheet, header, points);
        PointCharts charts;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (progress && !progress(i + 1, pages)) throw runtime::ReportCancelled();
            writePointPage(sheet, header, points[i], charts);
        }
        painter.end();
    }
    if (progress && !progress(pages, pages)) throw runtime::ReportCancelled();
    if (!file.commit())
        throw std::runtime_error("writing '" + path.toStdString() + "' failed: " + file.errorString().toStdString());
}

void ReportPdf::writeTitlePage(Sheet& sheet, const ReportHeader& header,
                               const std::vector<runtime::PointReport>& points) {
    sheet.text(tr("Quality report"), 18, true);
    sheet.text(tr("Machine: %1").arg(header.machines), 11);
    sheet.text(tr("Job: %1").arg(header.jobs), 11);
    sheet.text(tr("Runs: %1").arg(header.runs), 11);
    sheet.text(tr("Parts stored: %1").arg(header.dateRange), 11);
    sheet.text(
        tr("%n parts, %1", nullptr, static_cast<int>(header.parts)).arg(ReportCharts::chartDescription(points.front())),
        11);
    sheet.text(tr("Printed %1 UTC").arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd HH:mm"))),
               9);
    sheet.rule();
    sheet.text(tr("Point · x, mm · n · mean, mm · Cpk · Ppk · rule violations · good / rework / scrap"), 9, true);
    for (const runtime::PointReport& p : points) {
        const auto& c = p.analysis.capability;
        sheet.text(QStringLiteral("P%1 · %2 · %3 · %4 · %5 · %6 · %7 · %8 / %9 / %10")
                       .arg(p.pointIndex + 1)
                       .arg(p.zMm, 0, 'f', 1)
                       .arg(p.analysis.count)
                       .arg(p.analysis.meanMm, 0, 'f', 4)
                       .arg(c ? QString::number(c->indices.cpk, 'f', 2) : QStringLiteral("-"))
                       .arg(c ? QString::number(c->indices.ppk, 'f', 2) : QStringLiteral("-"))
                       .arg(p.analysis.violations.size())
                       .arg(p.verdicts.good)
                       .arg(p.verdicts.rework)
                       .arg(p.verdicts.scrap),
                   9, false, 8);
    }
    sheet.skip(6);
    writeSmallMultiples(sheet, points);
}

void ReportPdf::writeSmallMultiples(Sheet& sheet, const std::vector<runtime::PointReport>& points) {
    const int signatureHeight = 70;
    const int cell = sheet.width() / kSmallMultiplesPerRow;
    const int rows = static_cast<int>((points.size() + kSmallMultiplesPerRow - 1) / kSmallMultiplesPerRow);
    const int cellHeight = std::clamp((sheet.remaining() - signatureHeight) / std::max(rows, 1), 60, 230);
    auto multiple = printChart();
    const int top = sheet.y();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const int row = static_cast<int>(i) / kSmallMultiplesPerRow,
                  column = static_cast<int>(i) % kSmallMultiplesPerRow;
        if (top + (row + 1) * cellHeight > sheet.y() + sheet.remaining() - signatureHeight) break;
        ReportCharts::showLocation(*multiple, points[i], true, cell);
        multiple->setFontPointSize(7);
        sheet.chart(*multiple, QRect(column * cell, top + row * cellHeight, cell - 4, cellHeight - 4));
    }
    sheet.skip(std::min(rows * cellHeight, sheet.remaining() - signatureHeight) + 10);
    sheet.text(tr("Checked by: ______________________   Date: ____________   Signature: ______________________"), 10);
}

void ReportPdf::writePointPage(Sheet& sheet, const ReportHeader& header, const runtime::PointReport& p,
                               PointCharts& charts) {
    sheet.newPage();
    sheet.text(ReportCharts::pointTitle(p), 14, true);
    sheet.text(QStringLiteral("%1 · %2 · %3")
                   .arg(ReportCharts::chartDescription(p), ReportCharts::verdictText(p.verdicts),
                        tr("machine %1, job %2").arg(header.machines, header.jobs)),
               9);
    ReportCharts::showLocation(*charts.location, p, false, sheet.width());
    charts.location->setLegendBelow(5);  // the page is wide enough for one legend row
    charts.location->setFontPointSize(kChartFontPt);
    sheet.chart(*charts.location, sheet.take(290));
    ReportCharts::showSpread(*charts.spread, p, sheet.width());
    charts.spread->setFontPointSize(kChartFontPt);
    sheet.chart(*charts.spread, sheet.take(170));
    const QRect bottom = sheet.take(300);
    const int histogramWidth = bottom.width() * 58 / 100;
    ReportCharts::showHistogram(*charts.histogram, p);
    charts.histogram->setLegendBelow(2);
    charts.histogram->setFontPointSize(kChartFontPt);
    sheet.chart(*charts.histogram, QRect(bottom.left(), bottom.top(), histogramWidth, bottom.height()));
    sheet.table(ReportCharts::capabilityLines(p), histogramWidth + 12, bottom.top() + 10,
                bottom.width() - histogramWidth - 12);
    sheet.text(tr("Rule violations (Western Electric): %n", nullptr, static_cast<int>(p.analysis.violations.size())),
               10, true);
    for (const QString& line : ReportCharts::violationLines(p, 6))
        sheet.text(line, 9, false, 8);
    if (p.adaptations.empty()) return;
    sheet.text(tr("Controller changes of the adaptive loop (marked on the chart): %n", nullptr,
                  static_cast<int>(p.adaptations.size())),
               10, true);
    for (const QString& line : ReportCharts::adaptationLines(p, 4))
        sheet.text(line, 9, false, 8);
}

}  // namespace tt::reports
