#include "reports/report_charts.h"

#include <QColor>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "plot/chart.h"

namespace tt::reports {

namespace {

const QColor kData(30, 90, 160);
const QColor kCentre(40, 140, 60);
const QColor kLimit(200, 40, 40);
const QColor kViolation(230, 120, 0);
const QColor kSpec(120, 30, 150);
const QColor kFit(20, 20, 20);
const QColor kAdaptation(150, 40, 190);

/// 1, 2, ... n: the chart points' numbers on the x axis.
std::vector<double> pointNumbers(std::size_t n, std::size_t first = 0) {
    std::vector<double> xs(n);
    for (std::size_t i = 0; i < n; ++i)
        xs[i] = static_cast<double>(first + i + 1);
    return xs;
}

void horizontal(plot::Chart& chart, const QString& key, const QString& label, double xFirst, double xLast, double y,
                const QColor& color) {
    chart.setSeries(key, label, {xFirst, xLast}, {y, y}, color);
}

/// The chart points of every rule violation (the points meeting each rule's condition).
std::set<std::size_t> violationPoints(const runtime::PointReport& point) {
    std::set<std::size_t> points;
    for (const core::PointViolation& v : point.analysis.violations)
        points.insert(v.violation.points.begin(), v.violation.points.end());
    return points;
}

/// Vertical lines from `low` to `high` at the chart points where the controller changed (one line per point, broken
/// between them by a NaN).
void drawAdaptations(plot::Chart& chart, const runtime::PointReport& point, double low, double high, bool compact) {
    std::set<std::size_t> at;
    for (const runtime::ChartAdaptation& a : point.adaptations)
        at.insert(a.chartPoint);
    std::vector<double> xs, ys;
    for (std::size_t p : at) {
        const double x = static_cast<double>(p + 1);
        xs.insert(xs.end(), {x, x, x});
        ys.insert(ys.end(), {low, high, std::numeric_limits<double>::quiet_NaN()});
    }
    if (!xs.empty())
        chart.setSeries(
            QStringLiteral("adaptations"),
            compact ? QString() : QCoreApplication::translate("tt::reports::ReportCharts", "controller changed"), xs,
            ys, kAdaptation);
}

QString number(double v, int decimals = 4) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("-");
}

QString interval(const std::optional<core::ConfidenceInterval>& ci) {
    return ci ? QStringLiteral("%1 … %2").arg(number(ci->lower, 2), number(ci->upper, 2)) : QString();
}

}  // namespace

ChartSeries decimateMinMax(const std::vector<double>& xs, const std::vector<double>& ys, int columns) {
    if (columns < 1 || xs.size() <= 2 * static_cast<std::size_t>(columns) || xs.size() != ys.size()) return {xs, ys};
    ChartSeries out;
    out.xs.reserve(2 * static_cast<std::size_t>(columns));
    out.ys.reserve(2 * static_cast<std::size_t>(columns));
    const double first = xs.front();
    const double width = (xs.back() - first) / columns;
    const auto columnOf = [&](double x) {
        return width > 0.0 ? std::min(static_cast<int>((x - first) / width), columns - 1) : 0;
    };
    const auto keep = [&](std::size_t k) {
        out.xs.push_back(xs[k]);
        out.ys.push_back(ys[k]);
    };
    std::size_t i = 0;
    while (i < xs.size()) {
        const int column = columnOf(xs[i]);
        std::size_t end = i, low = i, high = i;
        for (; end < xs.size() && columnOf(xs[end]) == column; ++end) {
            if (ys[end] < ys[low]) low = end;
            if (ys[end] > ys[high]) high = end;
        }
        keep(std::min(low, high));
        if (low != high) keep(std::max(low, high));
        i = end;
    }
    return out;
}

ReportHistogram histogramOf(const runtime::PointReport& point) {
    const std::vector<double>& values = point.series.valuesMm;
    ReportHistogram h;
    if (values.empty()) return h;
    double lo = *std::min_element(values.begin(), values.end());
    double hi = *std::max_element(values.begin(), values.end());
    if (point.spec) {
        lo = std::min(lo, point.spec->lowerMm);
        hi = std::max(hi, point.spec->upperMm);
    }
    const auto bins =
        static_cast<std::size_t>(std::clamp(std::lround(std::sqrt(static_cast<double>(values.size()))), 5L, 30L));
    const double width = hi > lo ? (hi - lo) / static_cast<double>(bins) : 1e-3;
    h.firstEdgeMm = hi > lo ? lo : lo - width * static_cast<double>(bins) / 2.0;
    h.binWidthMm = width;
    h.counts.assign(bins, 0.0);
    for (std::size_t i = 0; i < bins; ++i)
        h.centresMm.push_back(h.firstEdgeMm + (static_cast<double>(i) + 0.5) * width);
    for (double v : values) {
        const auto bin = static_cast<std::size_t>(std::clamp((v - h.firstEdgeMm) / width, 0.0, bins - 0.5));
        h.counts[std::min(bin, bins - 1)] += 1.0;
    }
    return h;
}

PartProfile partProfileOf(const std::vector<storage::MeasurementRow>& rows, std::int64_t runId,
                          std::int64_t partNumber) {
    std::vector<const storage::MeasurementRow*> part;
    for (const storage::MeasurementRow& r : rows)
        if (r.runId == runId && r.partNumber == partNumber) part.push_back(&r);
    std::sort(part.begin(), part.end(), [](auto* a, auto* b) { return a->zMm < b->zMm; });
    PartProfile p;
    for (const storage::MeasurementRow* r : part) {
        p.zMm.push_back(r->zMm);
        p.measuredMm.push_back(r->measuredMm);
        p.nominalMm.push_back(r->nominalMm);
        p.lowerMm.push_back(r->lowerLimitMm.value_or(r->nominalMm));
        p.upperMm.push_back(r->upperLimitMm.value_or(r->nominalMm));
    }
    return p;
}

void ReportCharts::showLocation(plot::Chart& chart, const runtime::PointReport& point, bool compact, int columns) {
    const core::ControlChart& c = point.analysis.chart;
    const bool individuals = c.limits.kind == core::ChartKind::IndividualsMovingRange;
    chart.clear();
    if (!compact) chart.setLegendBelow(3);  // before the series: the legend wraps the entries added after
    const std::vector<double> xs = pointNumbers(c.locationMm.size());
    const double last = xs.empty() ? 1.0 : xs.back();
    chart.setTitle(compact ? pointTitle(point) : (individuals ? tr("Individual diameters") : tr("Subgroup means")));
    chart.setAxisTitles(individuals ? tr("part in order") : tr("subgroup"), compact ? tr("mm") : tr("diameter, mm"));
    const ChartSeries values = decimateMinMax(xs, c.locationMm, columns);
    chart.setSeries(QStringLiteral("values"), compact ? QString() : (individuals ? tr("diameter") : tr("mean")),
                    values.xs, values.ys, kData,
                    compact ? plot::Chart::Style::Line : plot::Chart::Style::LineAndPoints);
    horizontal(chart, QStringLiteral("centre"), compact ? QString() : tr("centre line"), 1.0, last,
               c.limits.location.centreMm, kCentre);
    horizontal(chart, QStringLiteral("ucl"), compact ? QString() : tr("control limits"), 1.0, last,
               c.limits.location.upperMm, kLimit);
    horizontal(chart, QStringLiteral("lcl"), QString(), 1.0, last, c.limits.location.lowerMm, kLimit);
    std::vector<double> vx, vy;
    for (std::size_t p : violationPoints(point)) {
        vx.push_back(xs[p]);
        vy.push_back(c.locationMm[p]);
    }
    const ChartSeries marked = decimateMinMax(vx, vy, columns);
    chart.setSeries(QStringLiteral("violations"), compact ? QString() : tr("rule violations"), marked.xs, marked.ys,
                    kViolation, compact ? plot::Chart::Style::SmallPoints : plot::Chart::Style::Points);
    const auto [lowest, highest] = std::minmax_element(c.locationMm.begin(), c.locationMm.end());
    const double low =
        lowest == c.locationMm.end() ? c.limits.location.lowerMm : std::min(*lowest, c.limits.location.lowerMm);
    const double high =
        highest == c.locationMm.end() ? c.limits.location.upperMm : std::max(*highest, c.limits.location.upperMm);
    const std::size_t baseline = c.limits.baselineFirstPoint + c.limits.baselinePointCount;
    if (!compact && baseline < c.locationMm.size()) {  // phase I | phase II
        const double x = static_cast<double>(baseline) + 0.5;
        chart.setSeries(QStringLiteral("baseline"), tr("end of the baseline"), {x, x}, {low, high}, kFit);
    }
    drawAdaptations(chart, point, low, high, compact);
    chart.rescale(false);
    chart.refresh();
}

void ReportCharts::showSpread(plot::Chart& chart, const runtime::PointReport& point, int columns) {
    const core::ControlChart& c = point.analysis.chart;
    chart.clear();
    const std::vector<double> xs = pointNumbers(c.spreadMm.size(), c.spreadFirstPoint);
    const double first = xs.empty() ? 1.0 : xs.front();
    const double last = xs.empty() ? 1.0 : xs.back();
    QString title;
    switch (c.limits.kind) {
        case core::ChartKind::XbarRange:
            title = tr("Subgroup ranges");
            break;
        case core::ChartKind::XbarStdDev:
            title = tr("Subgroup standard deviations");
            break;
        case core::ChartKind::IndividualsMovingRange:
            title = tr("Moving ranges");
            break;
    }
    chart.setTitle(title);
    chart.setAxisTitles(c.limits.kind == core::ChartKind::IndividualsMovingRange ? tr("part in order") : tr("subgroup"),
                        tr("spread, mm"));
    const ChartSeries values = decimateMinMax(xs, c.spreadMm, columns);
    chart.setSeries(QStringLiteral("values"), QString(), values.xs, values.ys, kData,
                    plot::Chart::Style::LineAndPoints);
    horizontal(chart, QStringLiteral("centre"), QString(), first, last, c.limits.spread.centreMm, kCentre);
    horizontal(chart, QStringLiteral("ucl"), QString(), first, last, c.limits.spread.upperMm, kLimit);
    if (c.limits.spread.lowerMm > 0.0)
        horizontal(chart, QStringLiteral("lcl"), QString(), first, last, c.limits.spread.lowerMm, kLimit);
    std::vector<double> bx, by;
    for (std::size_t p : c.spreadBeyondLimits) {
        bx.push_back(static_cast<double>(p + 1));
        by.push_back(c.spreadMm[p - c.spreadFirstPoint]);
    }
    const ChartSeries beyond = decimateMinMax(bx, by, columns);
    chart.setSeries(QStringLiteral("beyond"), QString(), beyond.xs, beyond.ys, kViolation, plot::Chart::Style::Points);
    chart.rescale(true);
    chart.refresh();
}

void ReportCharts::showHistogram(plot::Chart& chart, const runtime::PointReport& point) {
    const ReportHistogram h = histogramOf(point);
    chart.clear();
    chart.setLegendBelow(2);
    chart.setTitle(tr("Distribution"));
    chart.setAxisTitles(tr("diameter, mm"), tr("parts"));
    chart.setSeries(QStringLiteral("bins"), tr("parts"), h.centresMm, h.counts, kData, plot::Chart::Style::Steps);
    const double top = h.counts.empty() ? 1.0 : *std::max_element(h.counts.begin(), h.counts.end()) * 1.1;
    // The fitted normal density N(mean, sigma overall) in parts per bin.
    const double sigma = point.analysis.sigmaOverallMm;
    if (sigma > 0.0 && !h.centresMm.empty()) {
        std::vector<double> fx, fy;
        const double from = h.firstEdgeMm;
        const double to = h.firstEdgeMm + h.binWidthMm * static_cast<double>(h.counts.size());
        const double scale =
            static_cast<double>(point.analysis.count) * h.binWidthMm / (sigma * std::sqrt(2.0 * std::numbers::pi));
        for (int i = 0; i <= 120; ++i) {
            const double x = from + (to - from) * i / 120.0;
            const double z = (x - point.analysis.meanMm) / sigma;
            fx.push_back(x);
            fy.push_back(scale * std::exp(-0.5 * z * z));
        }
        chart.setSeries(QStringLiteral("normal"), tr("fitted normal"), fx, fy, kFit);
    }
    if (point.spec) {
        chart.setSeries(QStringLiteral("lsl"), tr("tolerance"), {point.spec->lowerMm, point.spec->lowerMm}, {0.0, top},
                        kSpec);
        chart.setSeries(QStringLiteral("usl"), QString(), {point.spec->upperMm, point.spec->upperMm}, {0.0, top},
                        kSpec);
    }
    chart.setSeries(QStringLiteral("nominal"), tr("nominal"), {point.nominalMm, point.nominalMm}, {0.0, top}, kCentre);
    chart.rescale(true);
    chart.setXTickCount(4);
    chart.refresh();
}

void ReportCharts::showProfile(plot::Chart& chart, const PartProfile& profile, const QString& title) {
    chart.clear();
    chart.setLegendBelow(3);
    chart.setTitle(title);
    chart.setAxisTitles(tr("x along the shaft, mm"), tr("diameter, mm"));
    chart.setBand(QStringLiteral("tolerance"), tr("tolerance band"), profile.zMm, profile.lowerMm, profile.upperMm,
                  kSpec);
    chart.setSeries(QStringLiteral("nominal"), tr("nominal"), profile.zMm, profile.nominalMm, kCentre);
    chart.setSeries(QStringLiteral("measured"), tr("measured"), profile.zMm, profile.measuredMm, kData,
                    plot::Chart::Style::LineAndPoints);
    chart.rescale(false);
    if (profile.zMm.size() > 1) {  // the end points whole, not cut by the axes
        const double margin = 0.04 * (profile.zMm.back() - profile.zMm.front());
        chart.setXRange(profile.zMm.front() - margin, profile.zMm.back() + margin);
    }
    chart.refresh();
}

std::vector<CapabilityLine> ReportCharts::capabilityLines(const runtime::PointReport& point) {
    const std::optional<core::CapabilityStudy>& c = point.analysis.capability;
    if (!c) return {{tr("Capability"), tr("no tolerance stored"), QString()}};
    const core::CapabilityIndices& i = c->indices;
    std::vector<CapabilityLine> lines{
        {tr("Cp"), number(i.cp, 2), interval(i.cpInterval)},
        {tr("Cpk"), number(i.cpk, 2), interval(i.cpkInterval)},
        {tr("Cpm"), i.cpm ? number(*i.cpm, 2) : QStringLiteral("-"), interval(i.cpmInterval)},
        {tr("Pp"), number(i.pp, 2), interval(i.ppInterval)},
        {tr("Ppk"), number(i.ppk, 2), interval(i.ppkInterval)},
        {tr("Method"),
         c->method == core::CapabilityMethod::Normal ? tr("normal distribution") : tr("percentiles (ISO 22514-2)"),
         QString()},
        {tr("Normality p (AD)"), number(c->normality.pValue, 3), QString()},
        {tr("σ within, mm"), number(c->sigmaWithinMm, 4), QString()},
        {tr("σ overall, mm"), number(c->sigmaOverallMm, 4), QString()},
        {tr("Mean, mm"), number(c->meanMm, 4), QString()},
        {tr("Tolerance, mm"),
         point.spec ? QStringLiteral("%1 … %2").arg(number(point.spec->lowerMm), number(point.spec->upperMm))
                    : QString(),
         QString()},
    };
    return lines;
}

QString ReportCharts::pointTitle(const runtime::PointReport& point) {
    return tr("Point %1 at x = %2 mm").arg(point.pointIndex + 1).arg(point.zMm, 0, 'f', 1);
}

QString ReportCharts::chartDescription(const runtime::PointReport& point) {
    const core::ChartLimits& l = point.analysis.chart.limits;
    const QString kind = QString::fromStdString(runtime::chartKindName(l.kind));
    if (l.kind == core::ChartKind::IndividualsMovingRange)
        return tr("%1 chart, limits from %n parts", nullptr, static_cast<int>(l.baselinePointCount)).arg(kind);
    return tr("%1 chart of subgroups of %2, limits from %n subgroups", nullptr, static_cast<int>(l.baselinePointCount))
        .arg(kind)
        .arg(l.subgroupSize);
}

QString ReportCharts::verdictText(const core::VerdictCounts& verdicts) {
    return tr("good %1 · rework %2 · scrap %3").arg(verdicts.good).arg(verdicts.rework).arg(verdicts.scrap);
}

QString ReportCharts::adaptationText(const core::AdaptationRecord& a) {
    namespace kind = core::adaptation_kind;
    if (a.kind == kind::kFallback) return tr("EWMA fallback (weight %1)").arg(a.fallbackWeight, 0, 'f', 2);
    const QString delay = a.modelAfter ? tr(", delay z = %1").arg(a.modelAfter->delayParts) : QString();
    if (a.kind == kind::kAccepted) return tr("proposed LQG applied%1").arg(delay);
    if (a.kind == kind::kRefined) return tr("LQG refined%1").arg(delay);
    return tr("LQG adapted%1").arg(delay);
}

QStringList ReportCharts::adaptationLines(const runtime::PointReport& point, int maxLines) {
    QStringList lines;
    for (const runtime::ChartAdaptation& a : point.adaptations) {
        if (lines.size() == maxLines) {
            lines << tr("… and %n more", nullptr, static_cast<int>(point.adaptations.size()) - maxLines);
            break;
        }
        lines << tr("Run %1, part %2: %3").arg(a.runId).arg(a.record.partNumber).arg(adaptationText(a.record));
    }
    return lines;
}

QStringList ReportCharts::violationLines(const runtime::PointReport& point, int maxLines) {
    QStringList lines;
    const auto& violations = point.analysis.violations;
    for (const core::PointViolation& v : violations) {
        if (lines.size() == maxLines) {
            lines << tr("… and %n more", nullptr, static_cast<int>(violations.size()) - maxLines);
            break;
        }
        QStringList parts;
        for (std::size_t i = 0; i < v.partNumbers.size() && i < 8; ++i)
            parts << QString::number(v.partNumbers[i]);
        if (v.partNumbers.size() > 8) parts << QStringLiteral("…");
        lines << tr("%1: parts %2")
                     .arg(QString::fromStdString(core::ruleCode(v.violation.set, v.violation.rule)),
                          parts.join(QStringLiteral(", ")));
    }
    return lines;
}

}  // namespace tt::reports
