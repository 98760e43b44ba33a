#include "ui/calibration/kp_wizard.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "ui/app_state.h"
#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/procedure_words.h"
#include "plot/chart.h"
#include "ui/prompt.h"

namespace tt::ui {

DeviceKpDrive* KpWizardContext::drive() const {
    if (drives.empty()) return nullptr;
    return drives[static_cast<std::size_t>(std::clamp(session->driveIndex, 0, static_cast<int>(drives.size()) - 1))];
}

QString KpWizardContext::operatorName() const {
    return app && app->state ? app->state->operatorName().trimmed() : QString();
}

// --- 1. Setup -----------------------------------------------------------------------------------

KpSetupPage::KpSetupPage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_driveLabel(new QLabel(this)),
      m_drive(new QComboBox(this)),
      m_toolsLabel(new QLabel(this)),
      m_tools(new QListWidget(this)),
      m_instructions(wrappedLabel(this)) {
    m_drive->setObjectName(QStringLiteral("driveCombo"));
    m_tools->setObjectName(QStringLiteral("kpTools"));
    m_tools->setMinimumHeight(160);
    m_tools->setStyleSheet(QStringLiteral("QListWidget::indicator { width: 28px; height: 28px; }"));
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_driveLabel, m_drive);
    form->addRow(m_toolsLabel, m_tools);
    form->addRow(m_instructions);
}

void KpSetupPage::initializePage() {
    const QSignalBlocker block(m_drive);
    m_drive->clear();
    for (DeviceKpDrive* d : m_ctx.drives)
        m_drive->addItem(d->name());
    m_drive->setCurrentIndex(std::clamp(m_ctx.session->driveIndex, 0, std::max(0, m_drive->count() - 1)));
    m_tools->clear();
    if (!m_ctx.tools) return;
    for (const core::ToolRecord& t : m_ctx.tools->tools()) {
        const QString id = QString::fromStdString(t.id);
        auto* item = new QListWidgetItem(tr("%1 %2 — k_p now %3 N/A")
                                             .arg(id, QString::fromStdString(t.name))
                                             .arg(t.currentToForceGainNPerA, 0, 'f', 1),
                                         m_tools);
        item->setData(Qt::UserRole, id);
        item->setSizeHint(QSize(0, 48));  // a row a gloved finger can hit
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(m_ctx.session->toolIds.contains(id) ? Qt::Checked : Qt::Unchecked);
    }
}

void KpSetupPage::setToolChecked(const QString& id, bool checked) {
    for (int i = 0; i < m_tools->count(); ++i)
        if (m_tools->item(i)->data(Qt::UserRole).toString() == id)
            m_tools->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

bool KpSetupPage::validatePage() {
    m_ctx.session->driveIndex = std::max(0, m_drive->currentIndex());
    m_ctx.session->toolIds.clear();
    for (int i = 0; i < m_tools->count(); ++i)
        if (m_tools->item(i)->checkState() == Qt::Checked)
            m_ctx.session->toolIds << m_tools->item(i)->data(Qt::UserRole).toString();
    return true;
}

void KpSetupPage::retranslate() {
    setTitle(tr("Drive and tools"));
    setSubTitle(tr("k_p turns the cross-feed motor current into force: P = k_p (I_fwd − I_rev) / 2."));
    m_driveLabel->setText(tr("Cross-feed drive"));
    m_toolsLabel->setText(tr("Write the new k_p into"));
    m_instructions->setText(
        tr("Put a dynamometer or a hydraulic jack with a gauge between the tool block and the workpiece so it "
           "pushes the tool towards the axis like the cutting force. Start the cross-feed dither (as for boring) and "
           "keep it running; at each load the current is averaged at constant velocity in both directions."));
}

// --- 2. Loads -----------------------------------------------------------------------------------

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

// --- 3. Fit -------------------------------------------------------------------------------------

KpFitPage::KpFitPage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_explanation(wrappedLabel(this)),
      m_checkLabel(new QLabel(this)),
      m_checkLoad(new QDoubleSpinBox(this)),
      m_check(new QPushButton(this)),
      m_checkResult(wrappedLabel(this)),
      m_timer(new QTimer(this)),
      m_chart(new plot::Chart(this)),
      m_residuals(new plot::Chart(this)) {
    m_explanation->setObjectName(QStringLiteral("kpExplanation"));
    m_explanation->setTextFormat(Qt::RichText);
    m_checkLoad->setObjectName(QStringLiteral("checkLoadSpin"));
    m_check->setObjectName(QStringLiteral("checkLoad"));
    m_checkResult->setObjectName(QStringLiteral("kpCheckResult"));
    m_checkLoad->setRange(-20000.0, 20000.0);
    m_checkLoad->setDecimals(0);
    m_checkLoad->setSingleStep(100.0);
    m_checkLoad->setMinimumWidth(170);
    m_chart->setMinimumSize(420, 260);
    m_residuals->setMinimumSize(420, 260);
    m_chart->setLegendCorner(Qt::AlignTop | Qt::AlignLeft);  // the load rises with ΔI
    auto* check = new QHBoxLayout;
    check->addWidget(m_checkLabel);
    check->addWidget(m_checkLoad);
    check->addWidget(m_check);
    check->addWidget(m_checkResult, 1);
    auto* charts = new QHBoxLayout;
    charts->addWidget(m_chart);
    charts->addWidget(m_residuals);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_explanation);
    layout->addLayout(check);
    layout->addLayout(charts, 1);
    m_timer->setInterval(100);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) step();
    });
    connect(m_check, &QPushButton::clicked, this, &KpFitPage::checkLoad);
}

void KpFitPage::initializePage() {
    core::KpCalibrationProcedure& proc = m_ctx.procedure();
    proc.back();  // from Accepted (Back from the save page) or Fit (Cancel) to the loads,
    proc.back();
    proc.next();  // and the fit made again
    proc.takeEvents();
    m_ctx.session->saved = false;  // a k_p saved from an earlier fit is not this one
    m_checkResult->clear();
    showFit();
    if (m_ctx.drive()) m_timer->start();
}

void KpFitPage::cleanupPage() {
    m_timer->stop();
    m_ctx.procedure().back();  // Fit → loads, which stay
    m_ctx.procedure().takeEvents();
}

bool KpFitPage::validatePage() {
    core::KpCalibrationProcedure& proc = m_ctx.procedure();
    const bool accepted = proc.accept();
    proc.takeEvents();
    if (!accepted) {
        m_checkResult->setText(
            tr("Not accepted: a verification load failed or is being measured. Measure it "
               "again, or go back to the loads."));
        markProblem(m_checkResult, true);
        return false;
    }
    m_timer->stop();
    return true;
}

bool KpFitPage::isComplete() const {
    return m_ctx.procedure().fitOutcome().fit.has_value();
}

bool KpFitPage::checking() const {
    return m_ctx.procedure().measuring();
}

QString KpFitPage::checkResult() const {
    return m_checkResult->text();
}

QString KpFitPage::explanation() const {
    return m_explanation->text();
}

void KpFitPage::setCheckLoadN(double loadN) {
    m_checkLoad->setValue(loadN);
}

bool KpFitPage::checkLoad() {
    core::KpCalibrationProcedure& proc = m_ctx.procedure();
    DeviceKpDrive* d = m_ctx.drive();
    if (!d || !proc.fitOutcome().fit) return false;
    if (proc.measuring()) {
        proc.abort();
        proc.takeEvents();
        m_check->setText(tr("Check load"));
        m_checkResult->clear();
        return false;
    }
    step(0.0);  // the samples queued so far were taken under the old load
    try {
        if (d->hasJack()) d->applyLoadN(m_checkLoad->value());
        proc.check(m_checkLoad->value());
    } catch (const std::exception& e) {
        m_checkResult->setText(QString::fromStdString(e.what()));
        return false;
    }
    m_check->setText(tr("Stop"));
    m_checkResult->setText(tr("Measuring the verification load…"));
    markProblem(m_checkResult, false);
    return true;
}

void KpFitPage::step(double elapsedS) {
    core::KpCalibrationProcedure& proc = m_ctx.procedure();
    DeviceKpDrive* d = m_ctx.drive();
    if (!d) return;
    proc.pump(d->readout(), elapsedS);
    for (const core::KpEvent& e : proc.takeEvents()) {
        m_checkResult->setText(ProcedureWords::kpEvent(e, proc.config().noSampleTimeoutS));
        if (e.check)
            markVerdict(m_checkResult, e.check->passed);
        else
            markProblem(m_checkResult, e.kind == core::KpEvent::Kind::MeasureFailed);
        m_check->setText(tr("Check load"));
    }
}

void KpFitPage::showFit() {
    const core::KpCalibrationProcedure& proc = m_ctx.procedure();
    const core::KpFitOutcome& outcome = proc.fitOutcome();
    m_chart->clear();
    m_residuals->clear();
    m_check->setEnabled(outcome.fit.has_value() && m_ctx.drive() != nullptr);
    if (!outcome.fit) {
        m_explanation->setText(QStringLiteral("<p style='color:#b71c1c'><b>%1</b></p>")
                                   .arg(tr("Refused: %1").arg(ProcedureWords::kpRefusal(outcome)).toHtmlEscaped()));
        emit completeChanged();
        return;
    }
    const core::KpFit& f = *outcome.fit;
    const std::vector<core::KpLoadPoint>& points = proc.points();
    m_explanation->setText(tr("<p><b>k_p = %1 N/A</b> (offset %2 N, R² %3, residual RMS %4 N) from %5 loads.</p>"
                              "<p>The straight line P = k_p ΔI + offset is fitted by least squares; the offset "
                              "should be small against the loads (it shows an asymmetry of the drive). Check it at "
                              "a load not used in the fit before going on.</p>")
                               .arg(f.kpNPerA, 0, 'f', 2)
                               .arg(f.offsetN, 0, 'f', 1)
                               .arg(f.r2, 0, 'f', 5)
                               .arg(f.rmsResidualN, 0, 'f', 1)
                               .arg(points.size()));
    std::vector<double> xs, ys;
    double lo = points.front().currentDifferenceA, hi = lo;
    for (const core::KpLoadPoint& p : points) {
        xs.push_back(p.currentDifferenceA);
        ys.push_back(p.loadN);
        lo = std::min(lo, p.currentDifferenceA);
        hi = std::max(hi, p.currentDifferenceA);
    }
    m_chart->setSeries(QStringLiteral("points"), tr("known loads"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                       plot::Chart::Style::Points);
    m_chart->setSeries(QStringLiteral("fit"), tr("k_p ΔI + offset"), {lo, hi},
                       {f.kpNPerA * lo + f.offsetN, f.kpNPerA * hi + f.offsetN}, QColor(0xc6, 0x28, 0x28));
    showAllWithMargin(*m_chart, xs, ys, true, 0.3);
    m_residuals->setSeries(QStringLiteral("residuals"), tr("residual"), ys, f.residualsN, QColor(0x2e, 0x7d, 0x32),
                           plot::Chart::Style::Points);
    showAllWithMargin(*m_residuals, ys, f.residualsN, true, 0.5);
    m_chart->refresh();
    m_residuals->refresh();
    emit completeChanged();
}

void KpFitPage::retranslate() {
    setTitle(tr("Fit and verify k_p"));
    setSubTitle(tr("Force against the current difference, then a verification load not used in the fit."));
    m_checkLabel->setText(tr("Verification load"));
    m_checkLoad->setSuffix(tr(" N"));
    m_check->setText(m_ctx.procedure().measuring() ? tr("Stop") : tr("Check load"));
    m_chart->setTitle(tr("Load against ΔI"));
    m_chart->setAxisTitles(tr("ΔI, A"), tr("Load, N"));
    m_residuals->setTitle(tr("Residuals"));
    m_residuals->setAxisTitles(tr("Load, N"), tr("Load − fit, N"));
}

// --- 4. Save ------------------------------------------------------------------------------------

KpSavePage::KpSavePage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_summary(wrappedLabel(this)),
      m_save(new QPushButton(this)),
      m_result(wrappedLabel(this)) {
    m_save->setObjectName(QStringLiteral("saveKp"));
    m_save->setProperty("role", QStringLiteral("primary"));
    m_result->setObjectName(QStringLiteral("kpSaveResult"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    auto* row = new QHBoxLayout;
    row->addWidget(m_save);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addWidget(m_result);
    layout->addStretch(1);
    connect(m_save, &QPushButton::clicked, this, &KpSavePage::save);
}

void KpSavePage::initializePage() {
    m_save->setEnabled(!m_ctx.session->saved);
    retranslate();
}

void KpSavePage::cleanupPage() {
    m_ctx.procedure().withdrawAcceptance();  // Back to the fit
}

bool KpSavePage::isComplete() const {
    return m_ctx.session->saved;
}

bool KpSavePage::save() {
    if (m_ctx.session->saved || !m_ctx.procedure().accepted()) return m_ctx.session->saved;
    const QString who = m_ctx.operatorName();
    if (who.isEmpty()) {
        if (m_ctx.app && m_ctx.app->prompt)
            m_ctx.app->prompt->warn(this, tr("Save k_p"), tr("Enter your name on the Settings page first."));
        m_result->setText(tr("Not saved: no operator name (Settings)."));
        markProblem(m_result, true);
        return false;
    }
    if (!m_ctx.calibrations || !m_ctx.tools) {
        m_result->setText(tr("The calibration database is not open."));
        markProblem(m_result, true);
        return false;
    }
    const core::KpFit& f = *m_ctx.procedure().fitOutcome().fit;
    try {
        std::vector<storage::ToolEdit> edits;
        for (core::ToolRecord t : m_ctx.tools->tools()) {
            if (!m_ctx.session->toolIds.contains(QString::fromStdString(t.id))) continue;
            const std::string id = t.id;
            t.currentToForceGainNPerA = f.kpNPerA;
            edits.push_back({id, t});
        }
        if (!edits.empty()) m_ctx.tools->apply(edits, who);
        storage::KpCalibrationRecord r;
        r.createdBy = who;
        DeviceKpDrive* d = m_ctx.drive();
        r.drive = d ? d->name() : QString();
        r.kpNPerA = f.kpNPerA;
        r.offsetN = f.offsetN;
        r.r2 = f.r2;
        QString csv = QStringLiteral("load_n,current_difference_a\n");
        for (const core::KpLoadPoint& c : m_ctx.procedure().points())
            csv += QStringLiteral("%1,%2\n").arg(c.loadN, 0, 'g', 10).arg(c.currentDifferenceA, 0, 'g', 10);
        r.pointsCsv = csv;
        r.appliedTo = m_ctx.session->toolIds.join(QLatin1Char(','));
        m_ctx.calibrations->saveKp(r);
    } catch (const std::exception& e) {
        m_result->setText(tr("Not saved: %1").arg(QString::fromStdString(e.what())));
        markProblem(m_result, true);
        return false;
    }
    m_ctx.session->saved = true;
    m_save->setEnabled(false);
    m_result->setText(m_ctx.session->toolIds.isEmpty()
                          ? tr("Saved. No tool was chosen, so the tool table is unchanged.")
                          : tr("Saved; k_p %1 N/A written into %2 (recorded in the tool audit).")
                                .arg(f.kpNPerA, 0, 'f', 2)
                                .arg(m_ctx.session->toolIds.join(QStringLiteral(", "))));
    markProblem(m_result, false);
    emit completeChanged();
    return true;
}

void KpSavePage::retranslate() {
    setTitle(tr("Save k_p"));
    setSubTitle(tr("The calibration is kept with your name; the chosen tools get the new k_p."));
    m_save->setText(tr("Save and write into the tools"));
    if (m_ctx.procedure().fitOutcome().fit)
        m_summary->setText(tr("k_p = %1 N/A, to be written into: %2.")
                               .arg(m_ctx.procedure().fitOutcome().fit->kpNPerA, 0, 'f', 2)
                               .arg(m_ctx.session->toolIds.isEmpty()
                                        ? tr("no tool (only the calibration is kept)")
                                        : m_ctx.session->toolIds.join(QStringLiteral(", "))));
}

// --- The wizard ---------------------------------------------------------------------------------

KpCalibrationWizard::KpCalibrationWizard(AppContext& app, KpSession& session, std::vector<DeviceKpDrive*> drives,
                                         storage::CalibrationStore* calibrations, storage::ToolStore* tools,
                                         QWidget* parent)
    : CalibrationWizard(QStringLiteral("kpWizard"), parent),
      m_ctx{&app, &session, std::move(drives), calibrations, tools} {
    m_setup = new KpSetupPage(m_ctx, this);
    m_loads = new KpLoadsPage(m_ctx, this);
    m_fit = new KpFitPage(m_ctx, this);
    m_save = new KpSavePage(m_ctx, this);
    setPage(SetupPage, m_setup);
    setPage(LoadsPage, m_loads);
    setPage(FitPage, m_fit);
    setPage(SavePage, m_save);
    retranslate();
}

QString KpCalibrationWizard::titleText() const {
    return tr("k_p from known loads");
}

}  // namespace tt::ui
