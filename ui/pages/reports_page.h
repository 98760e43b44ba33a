#pragma once

#include "runtime/reports/report_task.h"
#include "ui/page.h"
#include "ui/status_text.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace tt::ui {

class EmptyState;
class ReportFilterBar;
class ReportViews;

/// The quality engineer's page: choose machine, run, dates, chart and baseline; the control chart of a
/// point with its rule violations, the histogram with the tolerance and the fitted normal, the capability
/// table, a part's profile along the shaft, every point side by side; export as PDF, CSV and DFQ. The
/// history is read and analysed in a worker thread (progress, cancel); the statistics are core/quality's
/// (ui/reports, the same as `trueturn report`).
class ReportsPage : public Page {
    Q_OBJECT
public:
    explicit ReportsPage(AppContext& context, QWidget* parent = nullptr);
    QString title() const override;
    void retranslate() override;

    /// Reads the stored runs again (machine and run lists).
    void refresh();
    /// Shows the reports of `machine` (all its runs, any date) and analyses them.
    void showMachine(const QString& machine);
    /// Reads and analyses the chosen readings in the worker; `analysed` when done.
    void analyse();
    /// Writes the PDF report of the shown analysis to `path` (progress, cancel); false when cancelled or
    /// failed (the reason shown).
    bool exportPdf(const QString& path);
    /// Writes the shown readings as CSV or DFQ to `path` in the worker; `exported` when done.
    void exportFile(const QString& path, bool dfq);
    /// Asks the running task or export to stop.
    void cancel();

    ReportFilterBar* filterBar() const { return m_filter; }
    ReportViews* views() const { return m_views; }
    QLabel* status() const { return m_status; }
    QProgressBar* progress() const { return m_progress; }
    bool busy() const { return m_task.busy() || m_exportingPdf; }

signals:
    /// An analysis ended (shown, failed or cancelled).
    void analysed();
    /// A CSV or DFQ export ended.
    void exported();

protected:
    void showEvent(QShowEvent* event) override;

private:
    void setBusy(bool busy);
    void finished(const runtime::ReportTaskResult& result, bool cancelled);
    void askAndExport(int kind);
    void showEmpty();

    runtime::ReportTask m_task;
    std::vector<core::RunSummary> m_runs;
    QString m_problem;
    bool m_analysedOnce = false;
    bool m_exportingPdf = false;
    bool m_exportRunning = false;  ///< the task writes a CSV or DFQ file
    bool m_cancelPdf = false;
    ReportFilterBar* m_filter;
    QPushButton* m_analyse;
    QPushButton* m_pdf;
    QPushButton* m_csv;
    QPushButton* m_dfq;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QLabel* m_status;
    StatusText m_statusText;  ///< m_status's text, made again when the language changes
    QStackedWidget* m_stack;
    EmptyState* m_empty;
    ReportViews* m_views;
};

}  // namespace tt::ui
