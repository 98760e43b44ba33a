#include "ui/process/feed_chart_tabs.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QTableWidget>
#include <algorithm>

#include "plot/chart.h"

namespace tt::ui {

namespace {

const QColor kWith(46, 125, 50);
const QColor kWithout(198, 40, 40);
const QColor kSet(120, 120, 120);

std::vector<double> column(const core::FeedRun& run, double core::FeedSample::*member, double factor) {
    std::vector<double> out;
    out.reserve(run.samples.size());
    for (const core::FeedSample& s : run.samples)
        out.push_back(s.*member * factor);
    return out;
}

/// A colour from blue (first) to orange (last) for member `k` of `count`.
QColor familyColour(std::size_t k, std::size_t count) {
    const double f = count > 1 ? static_cast<double>(k) / static_cast<double>(count - 1) : 0.0;
    return QColor::fromHsvF(0.62 - 0.55 * f, 0.85, 0.8 - 0.15 * f);
}

}  // namespace

FeedChartTabs::FeedChartTabs(QWidget* parent)
    : QTabWidget(parent),
      m_feed(new plot::Chart(this)),
      m_opening(new plot::Chart(this)),
      m_current(new plot::Chart(this)),
      m_sweep(new plot::Chart(this)),
      m_table(new QTableWidget(this)) {
    setObjectName(QStringLiteral("feedCharts"));
    m_feed->setObjectName(QStringLiteral("feedChart"));
    m_sweep->setObjectName(QStringLiteral("feedSweepChart"));
    m_table->setObjectName(QStringLiteral("feedSweepTable"));
    for (plot::Chart* c : {m_feed, m_opening, m_current, m_sweep}) {
        c->setLegendBelow(3);
        c->setYTickCount(5);
    }
    m_opening->setLegendBelow(1);
    m_current->setLegendBelow(1);
    auto* regulator = new QWidget(this);
    auto* layout = new QHBoxLayout(regulator);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_opening, 1);
    layout->addWidget(m_current, 1);
    m_table->setColumnCount(6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAlternatingRowColors(true);
    addTab(m_feed, QString());
    addTab(regulator, QString());
    addTab(m_sweep, QString());
    addTab(m_table, QString());
    retranslate();
}

void FeedChartTabs::retranslate() {
    setTabText(FeedTab, tr("Feed"));
    setTabText(RegulatorTab, tr("Spool and magnet"));
    setTabText(SweepTab, tr("Sweep"));
    setTabText(SweepTableTab, tr("Sweep table"));
    m_feed->setAxisTitles(tr("time, s"), tr("feed, mm/s"));
    m_opening->setAxisTitles(tr("time, s"), tr("slot opening, mm"));
    m_current->setAxisTitles(tr("time, s"), tr("magnet current, mA"));
    m_sweep->setAxisTitles(tr("time, s"), tr("feed, mm/s"));
    plotRuns();
    plotSweep();
}

void FeedChartTabs::showRuns(const FeedStudyResult& result) {
    m_runs = std::make_shared<const FeedStudyResult>(result);
    plotRuns();
    setCurrentIndex(FeedTab);
}

void FeedChartTabs::showSweep(const FeedStudyResult& result) {
    m_sweepResult = std::make_shared<const FeedStudyResult>(result);
    plotSweep();
    setCurrentIndex(SweepTab);
}

void FeedChartTabs::plotRuns() {
    m_feed->setTitle(tr("Feed after the load step, with and without the regulator"));
    m_opening->setTitle(tr("Slot opening"));
    m_current->setTitle(tr("Magnet current"));
    if (!m_runs || m_runs->with.samples.empty()) return;
    const core::FeedRun& with = m_runs->with;
    const core::FeedRun& without = m_runs->without;
    const std::vector<double> t = column(with, &core::FeedSample::timeS, 1.0);
    const double setFeed = m_runs->scenario.params.setFeedMPerS * 1e3;
    m_feed->setSeries(QStringLiteral("set"), tr("set feed"), {t.front(), t.back()}, {setFeed, setFeed}, kSet);
    m_feed->setSeries(QStringLiteral("without"), tr("without regulator"), t,
                      column(without, &core::FeedSample::feedMPerS, 1e3), kWithout);
    m_feed->setSeries(QStringLiteral("with"), tr("with regulator"), t, column(with, &core::FeedSample::feedMPerS, 1e3),
                      kWith);
    m_opening->setSeries(QStringLiteral("without"), tr("without regulator"), t,
                         column(without, &core::FeedSample::openingM, 1e3), kWithout);
    m_opening->setSeries(QStringLiteral("with"), tr("with regulator"), t,
                         column(with, &core::FeedSample::openingM, 1e3), kWith);
    m_current->setSeries(QStringLiteral("without"), tr("without regulator"), t,
                         column(without, &core::FeedSample::currentA, 1e3), kWithout);
    m_current->setSeries(QStringLiteral("with"), tr("with regulator"), t,
                         column(with, &core::FeedSample::currentA, 1e3), kWith);
    for (plot::Chart* c : {m_feed, m_opening, m_current}) {
        c->rescale(true);
        c->refresh();
    }
}

QString FeedChartTabs::sweepValueText(double value) const {
    if (m_sweepResult && m_sweepResult->job == FeedStudyResult::Job::SweepXi)
        return QStringLiteral("ξ = %1").arg(QString::number(value, 'g', 3));
    if (m_sweepResult && m_sweepResult->regulator == core::FeedRegulator::Feedback)
        return QStringLiteral("%1 × K_p").arg(QString::number(value, 'g', 3));
    return QStringLiteral("Kₐ = %1").arg(QString::number(value, 'g', 4));
}

void FeedChartTabs::plotSweep() {
    const bool xi = !m_sweepResult || m_sweepResult->job == FeedStudyResult::Job::SweepXi;
    const bool feedback = m_sweepResult && m_sweepResult->regulator == core::FeedRegulator::Feedback;
    m_sweep->setTitle(xi ? tr("Feed after the load step for each ξ") : tr("Feed after the load step for each gain"));
    m_table->setHorizontalHeaderLabels({xi         ? tr("ξ")
                                        : feedback ? tr("gain ×\nK_p")
                                                   : tr("gain K_a"),
                                        tr("feed,\nmm/s"), tr("settling,\ns"), tr("overshoot,\n%"),
                                        tr("spool\novershoot, %"), tr("regulates")});
    if (!m_sweepResult) return;
    m_sweep->clear();
    const std::vector<core::FeedSweepPoint>& points = m_sweepResult->sweep;
    m_table->setRowCount(static_cast<int>(points.size()));
    for (std::size_t k = 0; k < points.size(); ++k) {
        const core::FeedSweepPoint& p = points[k];
        m_sweep->setSeries(QStringLiteral("member%1").arg(k), sweepValueText(p.value),
                           column(p.run, &core::FeedSample::timeS, 1.0),
                           column(p.run, &core::FeedSample::feedMPerS, 1e3), familyColour(k, points.size()));
        const QStringList cells = {
            QString::number(p.value, 'g', xi ? 3 : 4),
            QString::number(p.run.feed.finalValue * 1e3, 'f', 4),
            QString::number(p.run.feed.settlingS, 'f', 4) + (p.run.feed.settled ? QString() : QStringLiteral("+")),
            QString::number(p.run.feed.overshootPct, 'f', 2),
            QString::number(p.run.opening.overshootPct, 'f', 2),
            !p.stable             ? (feedback ? tr("no: unstable") : tr("no: runs away"))
            : p.run.slotFullyOpen ? tr("slot fully open")
                                  : tr("yes")};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(Qt::AlignCenter);
            if (c == 4 && p.oscillates) item->setForeground(QColor(178, 106, 0));
            m_table->setItem(static_cast<int>(k), c, item);
        }
    }
    m_sweep->rescale(false);  // the spool's swing shows near the set feed
    m_sweep->refresh();
}

}  // namespace tt::ui
