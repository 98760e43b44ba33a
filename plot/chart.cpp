#include "plot/chart.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>

namespace tt::plot {

namespace {

constexpr const char* kKeyProperty = "seriesKey";

QVector<double> toQVector(const std::vector<double>& v) {
    return QVector<double>(v.begin(), v.end());
}

void applyStyle(QCPGraph* graph, const QColor& color, Chart::Style style) {
    QPen pen(color);
    pen.setWidthF(2.5);
    graph->setPen(pen);
    const bool pointsOnly = style == Chart::Style::Points || style == Chart::Style::SmallPoints;
    graph->setLineStyle(pointsOnly                     ? QCPGraph::lsNone
                        : style == Chart::Style::Steps ? QCPGraph::lsStepCenter
                                                       : QCPGraph::lsLine);
    if (style == Chart::Style::Points || style == Chart::Style::LineAndPoints)
        graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, color, color, 9));
    else if (style == Chart::Style::SmallPoints)
        graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, color, color, 4));
    else
        graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssNone));
}

}  // namespace

Chart::Chart(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    QFont axisFont = font();
    axisFont.setPointSize(12);
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        axis->setLabelFont(axisFont);
        axis->setTickLabelFont(axisFont);
    }
    m_plot->legend->setVisible(false);  // shown once the chart has a named series
    m_plot->legend->setFont(axisFont);
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    setMinimumHeight(220);
}

void Chart::setTitle(const QString& title) {
    if (auto* element = qobject_cast<QCPTextElement*>(m_plot->plotLayout()->element(0, 0))) {
        element->setText(title);
        return;
    }
    m_plot->plotLayout()->insertRow(0);
    auto* element = new QCPTextElement(m_plot, title, QFont(font().family(), 13, QFont::Bold));
    m_plot->plotLayout()->addElement(0, 0, element);
}

void Chart::setYTickCount(int count) {
    m_plot->yAxis->ticker()->setTickCount(std::max(2, count));
}

void Chart::setXTickCount(int count) {
    m_plot->xAxis->ticker()->setTickCount(std::max(2, count));
}

void Chart::setLegendCorner(Qt::Alignment corner) {
    if (m_plot->legend->layout() == m_plot->axisRect()->insetLayout())
        m_plot->axisRect()->insetLayout()->setInsetAlignment(0, corner);
}

void Chart::setLegendBelow(int columns) {
    QCPLayoutGrid* layout = m_plot->plotLayout();
    if (m_plot->legend->layout() != layout) {
        m_plot->axisRect()->insetLayout()->take(m_plot->legend);
        layout->insertRow(layout->rowCount());
        layout->addElement(layout->rowCount() - 1, 0, m_plot->legend);
        layout->setRowStretchFactor(layout->rowCount() - 1, 0.001);
    }
    // A grid column is as wide as the smallest maximum of its elements, and a legend's maximum is
    // the width of its entries: without this a short (or empty) legend narrows the axes above it.
    constexpr int kUnlimitedWidth = 100000;
    m_plot->legend->setMaximumSize(kUnlimitedWidth, QWIDGETSIZE_MAX);
    m_plot->legend->setWrap(std::max(1, columns));
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);  // rearranges the entries already there
    m_plot->legend->setMargins(QMargins(4, 2, 4, 2));
    m_plot->plotLayout()->setMargins(QMargins(0, 0, 1, 1));  // the legend's frame inside the widget
}

void Chart::setAxisTitles(const QString& x, const QString& y) {
    m_plot->xAxis->setLabel(x);
    m_plot->yAxis->setLabel(y);
}

int Chart::graphIndex(const QString& key) const {
    for (int i = 0; i < m_plot->graphCount(); ++i)
        if (m_plot->graph(i)->property(kKeyProperty).toString() == key) return i;
    return -1;
}

void Chart::setSeries(const QString& key, const QString& label, const std::vector<double>& xs,
                      const std::vector<double>& ys, const QColor& color, Style style) {
    const int index = graphIndex(key);
    QCPGraph* graph = index >= 0 ? m_plot->graph(index) : m_plot->addGraph();
    graph->setProperty(kKeyProperty, key);
    graph->setName(label);
    graph->setData(toQVector(xs), toQVector(ys), true);
    applyStyle(graph, color, style);
    if (label.isEmpty()) graph->removeFromLegend();  // a series without a name has no legend entry
}

void Chart::setBand(const QString& key, const QString& label, const std::vector<double>& xs,
                    const std::vector<double>& lower, const std::vector<double>& upper, const QColor& color) {
    const QString upperKey = key + QStringLiteral("#upper");
    setSeries(key, label, xs, lower, color.darker(120));
    setSeries(upperKey, QString(), xs, upper, color.darker(120));
    QCPGraph* low = m_plot->graph(graphIndex(key));
    QCPGraph* high = m_plot->graph(graphIndex(upperKey));
    QColor fill = color;
    fill.setAlpha(60);
    low->setBrush(QBrush(fill));
    low->setChannelFillGraph(high);
    high->removeFromLegend();
}

void Chart::removeSeries(const QString& key) {
    for (const QString& k : {key, key + QStringLiteral("#upper")}) {
        const int index = graphIndex(k);
        if (index >= 0) m_plot->removeGraph(index);
    }
}

void Chart::clear() {
    m_plot->clearGraphs();
    showLegendWhenItHasEntries();
}

int Chart::pointCount(const QString& key) const {
    const int index = graphIndex(key);
    return index >= 0 ? m_plot->graph(index)->dataCount() : 0;
}

void Chart::rescale(bool includeZeroY) {
    m_plot->rescaleAxes(true);
    QCPRange y = m_plot->yAxis->range();
    if (includeZeroY) y.expand(0.0);
    const double margin = std::max(y.size() * 0.08, 1e-6);
    m_plot->yAxis->setRange(y.lower - margin, y.upper + margin);
}

void Chart::setXRange(double lower, double upper) {
    m_plot->xAxis->setRange(lower, upper);
}

void Chart::setYRange(double lower, double upper) {
    m_plot->yAxis->setRange(lower, upper);
}

void Chart::refresh() {
    showLegendWhenItHasEntries();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void Chart::showLegendWhenItHasEntries() {
    m_plot->legend->setVisible(m_plot->legend->itemCount() > 0);  // no empty box on an empty chart
}

void Chart::setFontPointSize(int pointSize) {
    QFont f = font();
    f.setPointSize(pointSize);
    for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
        axis->setLabelFont(f);
        axis->setTickLabelFont(f);
    }
    m_plot->legend->setFont(f);
    if (auto* element = qobject_cast<QCPTextElement*>(m_plot->plotLayout()->element(0, 0))) {
        f.setPointSize(pointSize + 1);
        f.setBold(true);
        element->setFont(f);
    }
}

void Chart::render(QCPPainter& painter, const QRect& target) {
    showLegendWhenItHasEntries();
    painter.save();
    painter.translate(target.topLeft());
    m_plot->toPainter(&painter, target.width(), target.height());
    painter.restore();
}

bool Chart::savePng(const QString& path, int width, int height) {
    showLegendWhenItHasEntries();
    m_plot->replot();
    return m_plot->savePng(path, width, height);
}

}  // namespace tt::plot
