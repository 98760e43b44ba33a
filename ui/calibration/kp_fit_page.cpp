#include "ui/calibration/kp_fit_page.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/kp_wizard_context.h"
#include "ui/calibration/procedure_words.h"
#include "plot/chart.h"

namespace tt::ui {

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

}  // namespace tt::ui
