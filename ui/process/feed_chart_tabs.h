#pragma once

#include <QTabWidget>
#include <memory>

#include "ui/process/feed_study_worker.h"

class QTableWidget;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

/// The Hydraulic feed tool's curves, one tab each: the feed with and without the regulator; the slot's
/// opening and the magnet current; the sweep as a family of feed curves; the sweep's table (settling
/// time, overshoot, steady feed for each value). Feed in mm/s, opening in mm, current in mA.
class FeedChartTabs : public QTabWidget {
    Q_OBJECT
public:
    enum Tab { FeedTab = 0, RegulatorTab = 1, SweepTab = 2, SweepTableTab = 3 };

    explicit FeedChartTabs(QWidget* parent = nullptr);

    /// Shows a Simulate result (both runs).
    void showRuns(const FeedStudyResult& result);
    /// Shows a sweep result and switches to its chart.
    void showSweep(const FeedStudyResult& result);
    void retranslate();

    plot::Chart* feedChart() const { return m_feed; }
    plot::Chart* sweepChart() const { return m_sweep; }
    QTableWidget* sweepTable() const { return m_table; }

private:
    void plotRuns();
    void plotSweep();
    QString sweepValueText(double value) const;

    plot::Chart* m_feed;
    plot::Chart* m_opening;
    plot::Chart* m_current;
    plot::Chart* m_sweep;
    QTableWidget* m_table;
    std::shared_ptr<const FeedStudyResult> m_runs;
    std::shared_ptr<const FeedStudyResult> m_sweepResult;
};

}  // namespace tt::ui
