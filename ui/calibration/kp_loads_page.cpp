#include "ui/calibration/kp_loads_page.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/kp_wizard_context.h"
#include "ui/calibration/procedure_words.h"
#include "plot/chart.h"

namespace tt::ui {

KpLoadsPage::KpLoadsPage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_timer(new QTimer(this)),
      m_live(new QLabel(this)),
      m_loadLabel(new QLabel(this)),
      m_load(new QDoubleSpinBox(this)),
      m_measure(new QPushButton(this)),
      m_repeat(new QPushButton(this)),
      m_typedLabel(new QLabel(this)),
      m_typed(new QDoubleSpinBox(this)),
      m_addTyped(new QPushButton(this)),
      m_remove(new QPushButton(this)),
      m_progress(new QProgressBar(this)),
      m_table(new QTableWidget(0, 3, this)),
      m_chart(new plot::Chart(this)),
      m_message(wrappedLabel(this)) {
    setUpControls();
    buildLayout();
    m_timer->setInterval(100);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) step();
    });
    connect(m_measure, &QPushButton::clicked, this, [this] {
        if (measuring())
            abortMeasurement();
        else
            startMeasurement();
    });
    connect(m_repeat, &QPushButton::clicked, this, &KpLoadsPage::repeatMeasurement);
    connect(m_addTyped, &QPushButton::clicked, this, &KpLoadsPage::addTypedPoint);
    connect(m_remove, &QPushButton::clicked, this, &KpLoadsPage::removePoint);
}

void KpLoadsPage::setUpControls() {
    m_live->setObjectName(QStringLiteral("liveDifference"));
    m_live->setStyleSheet(QStringLiteral("font-size: 16pt; font-weight: bold;"));
    m_load->setObjectName(QStringLiteral("loadSpin"));
    m_measure->setObjectName(QStringLiteral("measureLoad"));
    m_measure->setProperty("role", QStringLiteral("primary"));
    m_repeat->setObjectName(QStringLiteral("repeatLoad"));
    m_typed->setObjectName(QStringLiteral("typedCurrentSpin"));
    m_addTyped->setObjectName(QStringLiteral("addTypedLoad"));
    m_remove->setObjectName(QStringLiteral("removeLoad"));
    m_table->setObjectName(QStringLiteral("kpPoints"));
    m_message->setObjectName(QStringLiteral("kpMessage"));
    m_load->setRange(-20000.0, 20000.0);
    m_load->setDecimals(0);
    m_load->setSingleStep(100.0);
    m_typed->setRange(-500.0, 500.0);
    m_typed->setDecimals(3);
    for (QDoubleSpinBox* s : {m_load, m_typed})
        s->setMinimumWidth(150);
    m_progress->setRange(0, 100);
    m_table->verticalHeader()->setDefaultSectionSize(40);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_chart->setMinimumSize(340, 300);
    m_chart->setLegendCorner(Qt::AlignTop | Qt::AlignLeft);  // ΔI rises with the load
}

void KpLoadsPage::buildLayout() {
    auto* entry = new QGridLayout;
    entry->addWidget(m_loadLabel, 0, 0);
    entry->addWidget(m_load, 0, 1);
    entry->addWidget(m_measure, 0, 2);
    entry->addWidget(m_typedLabel, 1, 0);
    entry->addWidget(m_typed, 1, 1);
    entry->addWidget(m_addTyped, 1, 2);
    auto* left = new QVBoxLayout;
    left->addWidget(m_live);
    left->addLayout(entry);
    left->addWidget(m_progress);
    layOutCapturePage(this, left, m_table, {m_repeat, m_remove}, m_chart, m_message);
}

void KpLoadsPage::initializePage() {
    m_ctx.procedure().back();  // from the fit (after Cancel) to the loads
    m_ctx.procedure().back();
    refresh();
    retranslate();
    if (m_ctx.drive()) m_timer->start();
}

void KpLoadsPage::cleanupPage() {
    m_timer->stop();
    m_ctx.procedure().abort();
    m_ctx.procedure().takeEvents();
}

bool KpLoadsPage::isComplete() const {
    return m_ctx.procedure().canFit();
}

bool KpLoadsPage::measuring() const {
    return m_ctx.procedure().measuring();
}

void KpLoadsPage::setLoadN(double loadN) {
    m_load->setValue(loadN);
}

void KpLoadsPage::setTypedCurrentDifference(double a) {
    m_typed->setValue(a);
}

void KpLoadsPage::selectPoint(int row) {
    m_table->selectRow(row);
}

QString KpLoadsPage::message() const {
    return m_message->text();
}

void KpLoadsPage::showMessage(const QString& text, bool problem) {
    m_message->setText(text);
    markProblem(m_message, problem);
}

void KpLoadsPage::applyLoad(double loadN) {
    if (DeviceKpDrive* d = m_ctx.drive(); d && d->hasJack()) d->applyLoadN(loadN);
}

bool KpLoadsPage::startMeasurement() {
    if (!m_ctx.drive() || measuring()) return false;
    step(0.0);  // the samples queued so far were taken under the old load
    try {
        applyLoad(m_load->value());
        m_ctx.procedure().measure(m_load->value());
    } catch (const std::invalid_argument& e) {
        showMessage(QString::fromStdString(e.what()), true);
        return false;
    }
    refreshState();
    emit completeChanged();
    return true;
}

bool KpLoadsPage::repeatMeasurement() {
    const int row = selectedRowOrLast(m_table, static_cast<int>(m_ctx.procedure().points().size()));
    if (!m_ctx.drive() || measuring() || row < 0) return false;
    step(0.0);
    applyLoad(m_ctx.procedure().points()[static_cast<std::size_t>(row)].loadN);
    m_ctx.procedure().repeatPoint(row);
    refreshState();
    emit completeChanged();
    return true;
}

void KpLoadsPage::abortMeasurement() {
    m_ctx.procedure().abort();
    handleEvents();
    refreshState();
    emit completeChanged();
}

void KpLoadsPage::step(double elapsedS) {
    if (DeviceKpDrive* d = m_ctx.drive()) m_ctx.procedure().pump(d->readout(), elapsedS);
    handleEvents();
    refreshState();
}

void KpLoadsPage::handleEvents() {
    bool any = false;
    for (const core::KpEvent& e : m_ctx.procedure().takeEvents()) {
        showMessage(ProcedureWords::kpEvent(e, m_ctx.procedure().config().noSampleTimeoutS),
                    e.kind == core::KpEvent::Kind::MeasureFailed);
        any = true;
    }
    if (any) refresh();
}

void KpLoadsPage::refreshState() {
    const core::KpCalibrationProcedure& proc = m_ctx.procedure();
    DeviceKpDrive* d = m_ctx.drive();
    const core::DeviceHealth h = d ? d->readout().health() : core::DeviceHealth{};
    if (!d)
        m_live->setText(tr("No drive read-out: type the current differences"));
    else if (!h.ready())
        m_live->setText(tr("Drive read-out: %1").arg(QString::fromStdString(h.message)));
    else if (proc.liveDifferenceA())
        m_live->setText(tr("Live ΔI %1 A (last stroke pair)").arg(*proc.liveDifferenceA(), 0, 'f', 3));
    else
        m_live->setText(tr("Waiting for dither strokes…"));
    markProblem(m_live, d && !h.ready());
    if (proc.measuring()) {
        m_progress->setValue(static_cast<int>(std::lround(100.0 * proc.progress())));
        showMessage(
            proc.phase() == core::KpCalibrationProcedure::Phase::HoldStill
                ? tr("Measuring at %1 N: keep the load steady while it settles…").arg(proc.loadN(), 0, 'f', 0)
                : tr("Measuring at %1 N: %2 stroke pairs averaged…").arg(proc.loadN(), 0, 'f', 0).arg(proc.pairs()),
            false);
    }
    m_measure->setText(proc.measuring() ? tr("Stop") : tr("Measure"));
    m_measure->setEnabled(d != nullptr);
    m_repeat->setEnabled(d && !proc.measuring() && !proc.points().empty());
    for (QWidget* w : std::initializer_list<QWidget*>{m_addTyped, m_remove})
        w->setEnabled(!proc.measuring());
}

bool KpLoadsPage::addTypedPoint() {
    if (measuring()) return false;
    m_ctx.procedure().typePoint(m_load->value(), m_typed->value());
    handleEvents();
    return true;
}

void KpLoadsPage::removePoint() {
    const int row = selectedRowOrLast(m_table, static_cast<int>(m_ctx.procedure().points().size()));
    if (measuring() || row < 0) return;
    m_ctx.procedure().removePoint(row);
    handleEvents();
}

void KpLoadsPage::refresh() {
    const std::vector<core::KpLoadPoint>& points = m_ctx.procedure().points();
    m_table->setRowCount(static_cast<int>(points.size()));
    std::vector<double> xs, ys;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const int row = static_cast<int>(i);
        m_table->setItem(row, 0, new QTableWidgetItem(QString::number(points[i].loadN, 'f', 0)));
        m_table->setItem(row, 1, new QTableWidgetItem(QString::number(points[i].currentDifferenceA, 'f', 3)));
        m_table->item(row, 0)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->item(row, 1)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(
            row, 2,
            new QTableWidgetItem(points[i].pairs > 0 ? tr("measured, %1 pairs").arg(points[i].pairs) : tr("typed")));
        xs.push_back(points[i].loadN);
        ys.push_back(points[i].currentDifferenceA);
    }
    m_chart->setSeries(QStringLiteral("points"), tr("known loads"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                       plot::Chart::Style::Points);
    showAllWithMargin(*m_chart, xs, ys, true, 0.3);
    m_table->resizeColumnsToContents();
    m_chart->refresh();
    m_progress->setValue(0);
    refreshState();
    emit completeChanged();
}

void KpLoadsPage::retranslate() {
    setTitle(tr("Known loads"));
    m_load->setSuffix(tr(" N"));
    m_typed->setSuffix(tr(" A"));
    DeviceKpDrive* d = m_ctx.drive();
    setSubTitle(d && d->hasJack()
                    ? tr("The stand's hydraulic jack applies the load you enter. Measure at least 3 loads, 0 included.")
                    : tr("Apply the load, enter what the gauge shows, measure. At least 3 loads, 0 included."));
    m_loadLabel->setText(tr("Known load"));
    m_repeat->setText(tr("Repeat load"));
    m_typedLabel->setText(tr("ΔI (typed)"));
    m_addTyped->setText(tr("Add typed point"));
    m_remove->setText(tr("Remove point"));
    m_table->setHorizontalHeaderLabels({tr("Load, N"), tr("ΔI, A"), tr("Source")});
    m_chart->setTitle(tr("Current difference against the load"));
    m_chart->setAxisTitles(tr("Load, N"), tr("ΔI, A"));
    refreshState();
}

}  // namespace tt::ui
