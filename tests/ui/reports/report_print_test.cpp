// The printed report's charts are decimated per printed pixel column, keeping each column's lowest and highest
// point: every excursion stays, and the chart drawn from the decimated series looks the same at print size as the
// one drawn from every reading (compared pixel by pixel at 300 dpi).
#include <gtest/gtest.h>

#include <qcustomplot.h>

#include <QImage>
#include <cmath>
#include <random>

#include "plot/chart.h"
#include "runtime/reports/point_report.h"
#include "reports/report_charts.h"

namespace tt::reports {
namespace {

/// 20,000 diameters around 27 mm: slow drift, scatter and a few single excursions (the kind a decimation by
/// sampling would lose).
storage::PointReadings readings() {
    storage::PointReadings r;
    r.pointIndex = 0;
    r.zMm = 10.0;
    r.nominalMm = 27.0;
    r.lowerLimitMm = 26.979;
    r.upperLimitMm = 27.0;
    r.limitsNominalMm = 27.0;
    std::mt19937_64 random(5);
    std::normal_distribution<double> scatter(0.0, 0.003);
    double drift = 0.0;
    for (int i = 0; i < 20000; ++i) {
        drift = 0.95 * drift + 0.0003 * scatter(random) / 0.003;
        double v = 27.0 - 0.0105 + drift + scatter(random);
        if (i % 4999 == 1234) v += 0.05;  // four excursions far above the rest
        r.valuesMm.push_back(v);
        r.partNumbers.push_back(i + 1);
        r.timesS.push_back(60.0 * i);
    }
    return r;
}

/// The chart painted at `dpi` into an image, as the PDF paints it (logical units of 96 dpi).
QImage printed(plot::Chart& chart, const QSize& logical, int dpi) {
    const double scale = dpi / 96.0;
    QImage image(static_cast<int>(logical.width() * scale), static_cast<int>(logical.height() * scale),
                 QImage::Format_RGB32);
    image.fill(Qt::white);
    QCPPainter painter(&image);
    painter.setMode(QCPPainter::pmNoCaching);
    painter.scale(scale, scale);
    chart.resize(logical);
    chart.render(painter, QRect(QPoint(0, 0), logical));
    painter.end();
    return image;
}

TEST(ReportPrint, DecimationKeepsEachColumnsLowestAndHighestPoint) {
    const storage::PointReadings r = readings();
    std::vector<double> xs;
    for (std::size_t i = 0; i < r.valuesMm.size(); ++i)
        xs.push_back(static_cast<double>(i + 1));
    constexpr int kColumns = 680;
    const ChartSeries d = decimateMinMax(xs, r.valuesMm, kColumns);
    EXPECT_LE(d.xs.size(), 2u * kColumns);
    EXPECT_GT(d.xs.size(), static_cast<std::size_t>(kColumns));
    EXPECT_TRUE(std::is_sorted(d.xs.begin(), d.xs.end()));
    // Per column the same lowest and highest value as every reading's.
    const double width = (xs.back() - xs.front()) / kColumns;
    std::vector<double> lo(kColumns, 1e9), hi(kColumns, -1e9), dlo(kColumns, 1e9), dhi(kColumns, -1e9);
    const auto column = [&](double x) { return std::min(static_cast<int>((x - xs.front()) / width), kColumns - 1); };
    for (std::size_t i = 0; i < xs.size(); ++i) {
        lo[column(xs[i])] = std::min(lo[column(xs[i])], r.valuesMm[i]);
        hi[column(xs[i])] = std::max(hi[column(xs[i])], r.valuesMm[i]);
    }
    for (std::size_t i = 0; i < d.xs.size(); ++i) {
        dlo[column(d.xs[i])] = std::min(dlo[column(d.xs[i])], d.ys[i]);
        dhi[column(d.xs[i])] = std::max(dhi[column(d.xs[i])], d.ys[i]);
    }
    EXPECT_EQ(dlo, lo);
    EXPECT_EQ(dhi, hi);
    // A short series is drawn as it is.
    const std::vector<double> few{1.0, 2.0, 3.0};
    EXPECT_EQ(decimateMinMax(few, few, kColumns).xs, few);
}

/// The share of the inked pixels of `a` that differ in `b` (sum of the channels' differences above 96 of 765).
double differingShare(const QImage& a, const QImage& b) {
    std::int64_t different = 0, inked = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (p != qRgb(255, 255, 255)) ++inked;
            const int d = std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q));
            if (d > 96) ++different;
        }
    return static_cast<double>(different) / static_cast<double>(std::max<std::int64_t>(inked, 1));
}

// The diameters' line and markers, decimated to the chart's 680 printed columns, drawn at 300 dpi: the same
// picture as every reading's (the rule violations' markers, which overlap ten to a column here, are left out:
// their thinning to each column's extremes is checked above).
TEST(ReportPrint, TheDecimatedChartLooksTheSameAtPrintSize) {
    runtime::PointReport report = runtime::pointReportOf(readings(), runtime::reportSettings(1, runtime::ReportChart::Automatic, 0));
    report.analysis.violations.clear();
    const QSize logical(680, 290);  // the location chart's box on the PDF page
    plot::Chart every, decimated;
    for (plot::Chart* c : {&every, &decimated}) {
        c->setAttribute(Qt::WA_DontShowOnScreen);
        c->setFontPointSize(8);
    }
    ReportCharts::showLocation(every, report, false, 0);
    ReportCharts::showLocation(decimated, report, false, logical.width());
    EXPECT_LE(decimated.pointCount(QStringLiteral("values")), 2 * logical.width());
    EXPECT_EQ(every.pointCount(QStringLiteral("values")), 20000);
    const QImage a = printed(every, logical, 300), b = printed(decimated, logical, 300);
    ASSERT_EQ(a.size(), b.size());
    const double share = differingShare(a, b);
    EXPECT_LT(share, 0.005) << share;
    std::printf("inked pixels differing at 300 dpi: %.4f %%\n", 100.0 * share);
    a.save(QStringLiteral(TRUETURN_BINARY_DIR "/screenshots/report_print_every.png"));
    b.save(QStringLiteral(TRUETURN_BINARY_DIR "/screenshots/report_print_decimated.png"));
}

}  // namespace
}  // namespace tt::reports
