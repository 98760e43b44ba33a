#include "ui/pages/measurements_page.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTableView>
#include <QVBoxLayout>

#include "core/storage/history_store.h"
#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/run/measurements_model.h"

namespace tt::ui {

MeasurementsPage::MeasurementsPage(AppContext& context, QWidget* parent)
    : Page(PageId::Measurements, context, parent),
      m_runLabel(new QLabel(this)),
      m_runs(new QComboBox(this)),
      m_onlyProblems(new QCheckBox(this)),
      m_refresh(new QPushButton(this)),
      m_summary(new QLabel(this)),
      m_stack(new QStackedWidget(this)),
      m_empty(new EmptyState(this)),
      m_table(new QTableView(this)),
      m_model(new MeasurementsModel(this)) {
    m_runs->setObjectName(QStringLiteral("runCombo"));
    m_runs->setMinimumWidth(480);
    // A long run description is elided in the box (whole in the list), never widening the window.
    m_runs->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_runs->setMinimumContentsLength(36);
    m_runs->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    m_onlyProblems->setObjectName(QStringLiteral("onlyProblemsCheck"));
    m_refresh->setObjectName(QStringLiteral("refreshButton"));
    m_summary->setObjectName(QStringLiteral("measurementSummary"));
    m_summary->setWordWrap(true);
    m_table->setObjectName(QStringLiteral("measurementTable"));
    m_table->setModel(m_model);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(34);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(MeasurementsModel::Reason, QHeaderView::Stretch);
    m_stack->addWidget(m_empty);
    m_stack->addWidget(m_table);

    auto* bar = new QHBoxLayout;
    bar->addWidget(m_runLabel);
    bar->addWidget(m_runs);
    bar->addSpacing(16);
    bar->addWidget(m_onlyProblems);
    bar->addStretch(1);
    bar->addWidget(m_refresh);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 16, 24, 16);
    layout->addLayout(bar);
    layout->addWidget(m_summary);
    layout->addWidget(m_stack, 1);

    connect(m_refresh, &QPushButton::clicked, this, &MeasurementsPage::refresh);
    connect(m_runs, &QComboBox::activated, this, [this] { loadRun(); });
    connect(m_onlyProblems, &QCheckBox::toggled, this, [this] { loadRun(); });
    retranslate();
}

MeasurementsPage::~MeasurementsPage() = default;

QString MeasurementsPage::title() const {
    return pageTitle(PageId::Measurements);
}

void MeasurementsPage::retranslate() {
    m_runLabel->setText(tr("Run"));
    m_onlyProblems->setText(tr("Only rejected and unmeasured"));
    m_refresh->setText(tr("Refresh"));
    if (m_stack->currentWidget() == m_empty) {
        if (!m_problem.isEmpty())
            m_empty->setTexts(tr("The run history cannot be read"), m_problem);
        else
            m_empty->setTexts(tr("No parts recorded yet"),
                              tr("Start a run on the Run page: every measured part appears here with its "
                                 "diameters at the control points, whether each was accepted and why not."));
    }
}

void MeasurementsPage::showEvent(QShowEvent* event) {
    Page::showEvent(event);
    refresh();
}

bool MeasurementsPage::openHistory() {
    m_history = context().data().history();
    m_problem = m_history ? QString() : context().data().problem();
    return m_history != nullptr;
}

QString MeasurementsPage::controllerName(const std::string& controller) {
    if (controller == "lqg") return tr("LQG");
    if (controller == "ewma") return tr("EWMA");
    if (controller == "open") return tr("open loop");
    return QString::fromStdString(controller);
}

QString MeasurementsPage::runStatusName(const std::string& status) {
    if (status == "complete") return tr("complete");
    if (status == "stopped") return tr("stopped");
    // A run stays "running" in the history until it ends; one that was cut off keeps it.
    if (status == "running") return tr("not finished");
    return QString::fromStdString(status);
}

void MeasurementsPage::refresh() {
    const qint64 chosen = m_runs->currentData().toLongLong();
    m_runs->clear();
    if (!openHistory()) {
        m_stack->setCurrentWidget(m_empty);
        m_summary->clear();
        retranslate();
        return;
    }
    try {
        for (const core::RunSummary& run : m_history->runs())
            m_runs->addItem(
                tr("Run %1 · %2 · %3, z = %4 · %5 parts · %6")
                    .arg(run.runId)
                    .arg(QString::fromStdString(run.description.preset), controllerName(run.description.controller))
                    .arg(run.description.delayParts)
                    .arg(run.partCount)
                    .arg(runStatusName(run.status)),
                QVariant::fromValue<qint64>(run.runId));
    } catch (const std::exception& e) {
        m_problem = QString::fromStdString(e.what());
    }
    const int index = m_runs->findData(QVariant::fromValue<qint64>(chosen));
    m_runs->setCurrentIndex(index >= 0 ? index : 0);
    loadRun();
}

void MeasurementsPage::loadRun() {
    if (!m_history || m_runs->count() == 0) {
        m_model->setParts({}, false);
        m_stack->setCurrentWidget(m_empty);
        m_summary->clear();
        retranslate();
        return;
    }
    try {
        const auto parts = m_history->parts(m_runs->currentData().toLongLong());
        m_model->setParts(parts, m_onlyProblems->isChecked());
        qint64 measured = 0;
        for (const core::StoredPart& p : parts)
            if (p.measurement) ++measured;
        m_summary->setText(tr("%1 parts recorded, %2 measured; %3 values rejected or not measured.")
                               .arg(parts.size())
                               .arg(measured)
                               .arg(m_model->problemCount()));
        m_stack->setCurrentWidget(m_table);
        // Whole reasons for a short list (the rejected ones); a long run keeps one line per row.
        if (m_model->rowCount() <= 200) m_table->resizeRowsToContents();
    } catch (const std::exception& e) {
        m_problem = QString::fromStdString(e.what());
        m_stack->setCurrentWidget(m_empty);
        retranslate();
    }
}

}  // namespace tt::ui
