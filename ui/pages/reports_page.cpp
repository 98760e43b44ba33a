#include "ui/pages/reports_page.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QVBoxLayout>

#include "reports/report_pdf.h"
#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/prompt.h"
#include "ui/reports/report_filter_bar.h"
#include "ui/reports/report_views.h"

namespace tt::ui {

namespace {

enum ExportKind { Pdf, Csv, Dfq };

}  // namespace

ReportsPage::ReportsPage(AppContext& context, QWidget* parent)
    : Page(PageId::Reports, context, parent),
      m_filter(new ReportFilterBar(this)),
      m_analyse(new QPushButton(this)),
      m_pdf(new QPushButton(this)),
      m_csv(new QPushButton(this)),
      m_dfq(new QPushButton(this)),
      m_progress(new QProgressBar(this)),
      m_cancel(new QPushButton(this)),
      m_status(new QLabel(this)),
      m_statusText(m_status),
      m_stack(new QStackedWidget(this)),
      m_empty(new EmptyState(this)),
      m_views(new ReportViews(this)) {
    m_analyse->setObjectName(QStringLiteral("reportAnalyse"));
    m_analyse->setProperty("role", QStringLiteral("primary"));
    m_pdf->setObjectName(QStringLiteral("reportExportPdf"));
    m_csv->setObjectName(QStringLiteral("reportExportCsv"));
    m_dfq->setObjectName(QStringLiteral("reportExportDfq"));
    m_cancel->setObjectName(QStringLiteral("reportCancel"));
    m_status->setObjectName(QStringLiteral("reportStatus"));
    m_status->setWordWrap(true);
    m_progress->setRange(0, 100);
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    m_stack->addWidget(m_empty);
    m_stack->addWidget(m_views);

    auto* actions = new QHBoxLayout;
    actions->addWidget(m_analyse);
    actions->addWidget(m_progress, 1);
    actions->addWidget(m_cancel);
    actions->addWidget(m_status, 2);
    actions->addWidget(m_pdf);
    actions->addWidget(m_csv);
    actions->addWidget(m_dfq);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 8, 16, 8);
    layout->addWidget(m_filter);
    layout->addLayout(actions);
    layout->addWidget(m_stack, 1);

    connect(&m_task, &runtime::ReportTask::progress, m_progress, &QProgressBar::setValue);
    connect(&m_task, &runtime::ReportTask::finished, this, &ReportsPage::finished);
    connect(m_analyse, &QPushButton::clicked, this, &ReportsPage::analyse);
    connect(m_cancel, &QPushButton::clicked, this, &ReportsPage::cancel);
    connect(m_pdf, &QPushButton::clicked, this, [this] { askAndExport(Pdf); });
    connect(m_csv, &QPushButton::clicked, this, [this] { askAndExport(Csv); });
    connect(m_dfq, &QPushButton::clicked, this, [this] { askAndExport(Dfq); });
    setBusy(false);
    retranslate();
}

QString ReportsPage::title() const {
    return pageTitle(PageId::Reports);
}

void ReportsPage::retranslate() {
    m_filter->retranslate();
    m_views->retranslate();
    m_analyse->setText(tr("Analyse"));
    m_pdf->setText(tr("PDF…"));
    m_csv->setText(tr("CSV…"));
    m_dfq->setText(tr("DFQ…"));
    m_cancel->setText(tr("Cancel"));
    m_statusText.retranslate();
    if (m_stack->currentWidget() == m_empty) showEmpty();
}

void ReportsPage::showEmpty() {
    m_stack->setCurrentWidget(m_empty);
    if (!m_problem.isEmpty())
        m_empty->setTexts(tr("No report"), m_problem);
    else
        m_empty->setTexts(tr("No measured parts for this choice"),
                          tr("Every part measured on the Run page is stored with its diameters and verdicts. Choose "
                             "the machine, run and dates, then Analyse: control charts, capability and exports."));
}

void ReportsPage::showEvent(QShowEvent* event) {
    Page::showEvent(event);
    refresh();
    if (!m_analysedOnce && !m_runs.empty()) analyse();
}

void ReportsPage::refresh() {
    storage::DataStores& data = context().data();
    m_problem.clear();
    m_runs.clear();
    try {
        if (storage::SqlHistoryStore* history = data.history())
            m_runs = history->runs();
        else
            m_problem = data.problem();
    } catch (const std::exception& e) {
        m_problem = QString::fromStdString(e.what());
    }
    m_filter->setRuns(m_runs);
    if (m_stack->currentWidget() == m_empty) showEmpty();
}

void ReportsPage::showMachine(const QString& machine) {
    if (busy()) cancel();
    refresh();
    m_filter->selectMachine(machine);
    m_analysedOnce = true;  // the page's first showing analyses this choice, not the default one
    analyse();
}

void ReportsPage::setBusy(bool busy) {
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    m_progress->setValue(0);
    m_filter->setEnabled(!busy);
    m_analyse->setEnabled(!busy);
    const bool haveReport = !busy && !m_views->points().empty() && m_stack->currentWidget() == m_views;
    for (QPushButton* b : {m_pdf, m_csv, m_dfq})
        b->setEnabled(haveReport);
}

void ReportsPage::analyse() {
    if (busy()) return;
    core::PointAnalysisSettings settings;
    try {
        settings = m_filter->settings();
    } catch (const std::invalid_argument& e) {
        m_statusText.setFixed(QString::fromStdString(e.what()));
        return;
    }
    m_analysedOnce = true;
    m_statusText.set([] { return tr("Reading the history…"); });
    setBusy(true);
    try {
        m_task.analyse(context().data().config(), m_filter->filter(), settings);
    } catch (const std::exception& e) {
        setBusy(false);
        m_statusText.setFixed(QString::fromStdString(e.what()));
        emit analysed();
    }
}

void ReportsPage::finished(const runtime::ReportTaskResult& result, bool cancelled) {
    if (cancelled) {
        m_statusText.set([] { return tr("Cancelled."); });
    } else if (!result.error.isEmpty()) {
        m_statusText.setFixed(result.error);
    } else if (!result.writtenFile.isEmpty()) {
        m_statusText.set([file = result.writtenFile] { return tr("Written: %1").arg(file); });
    } else if (result.points.empty()) {
        m_problem.clear();
        m_views->show({}, {});
        showEmpty();
        m_statusText.set([] { return tr("No measured parts for this choice."); });
    } else {
        const std::size_t rows = result.rows.size();
        m_runs = result.runs;
        m_views->show(result.rows, result.points, result.adaptationsError);
        m_stack->setCurrentWidget(m_views);
        m_statusText.set([rows] { return tr("%n readings", nullptr, static_cast<int>(rows)); });
    }
    setBusy(false);
    if (m_exportRunning) {
        m_exportRunning = false;
        emit exported();
    } else {
        emit analysed();
    }
}

void ReportsPage::askAndExport(int kind) {
    if (!context().prompt || busy()) return;
    const QString title = kind == Pdf   ? tr("Save the PDF report")
                          : kind == Csv ? tr("Save the readings as CSV")
                                        : tr("Save the readings as DFQ");
    const QString filter = kind == Pdf   ? tr("PDF files (*.pdf)")
                           : kind == Csv ? tr("CSV files (*.csv)")
                                         : tr("AQDEF files (*.dfq)");
    const QString suggested = kind == Pdf   ? QStringLiteral("report.pdf")
                              : kind == Csv ? QStringLiteral("readings.csv")
                                            : QStringLiteral("readings.dfq");
    const QString path = context().prompt->saveFileName(this, title, suggested, filter);
    if (path.isEmpty()) return;
    if (kind == Pdf)
        exportPdf(path);
    else
        exportFile(path, kind == Dfq);
}

bool ReportsPage::exportPdf(const QString& path) {
    if (busy() || m_views->points().empty()) return false;
    // The charts are widgets: the PDF is painted here, page by page, the window kept alive between pages.
    m_exportingPdf = true;
    m_cancelPdf = false;
    setBusy(true);
    m_statusText.set([] { return tr("Writing the PDF…"); });
    bool written = false;
    try {
        reports::ReportPdf::write(
            path, reports::reportHeaderOf(m_views->rows(), m_runs), m_views->points(),
            [this](std::size_t done, std::size_t total) {
                m_progress->setValue(static_cast<int>(100 * done / std::max<std::size_t>(total, 1)));
                QCoreApplication::processEvents();
                return !m_cancelPdf;
            });
        m_statusText.set([path] { return tr("Written: %1").arg(path); });
        written = true;
    } catch (const runtime::ReportCancelled&) {
        m_statusText.set([] { return tr("Cancelled."); });
    } catch (const std::exception& e) {
        m_statusText.setFixed(QString::fromStdString(e.what()));
    }
    m_exportingPdf = false;
    setBusy(false);
    return written;
}

void ReportsPage::exportFile(const QString& path, bool dfq) {
    if (busy() || m_views->rows().empty()) return;
    m_exportRunning = true;
    setBusy(true);
    m_statusText.set([dfq] { return dfq ? tr("Writing the DFQ file…") : tr("Writing the CSV file…"); });
    m_task.writeFile(m_views->rows(), path, dfq);
}

void ReportsPage::cancel() {
    m_cancelPdf = true;
    m_task.cancel();
}

}  // namespace tt::ui
