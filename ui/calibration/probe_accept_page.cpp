#include "ui/calibration/probe_accept_page.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/storage/calibration_store.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_wizard_context.h"
#include "ui/calibration/procedure_words.h"

namespace tt::ui {

ProbeAcceptPage::ProbeAcceptPage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_summary(wrappedLabel(this)),
      m_checkTitle(new QLabel(this)),
      m_jackLabel(new QLabel(this)),
      m_jack(new QDoubleSpinBox(this)),
      m_setJack(new QPushButton(this)),
      m_referenceLabel(new QLabel(this)),
      m_reference(new QDoubleSpinBox(this)),
      m_check(new QPushButton(this)),
      m_result(wrappedLabel(this)),
      m_accept(new QCheckBox(this)),
      m_timer(new QTimer(this)) {
    m_accept->setObjectName(QStringLiteral("acceptCheck"));
    m_accept->setStyleSheet(
        QStringLiteral("QCheckBox { font-weight: bold; } QCheckBox::indicator { width: 28px; height: 28px; }"));
    m_summary->setObjectName(QStringLiteral("acceptSummary"));
    m_summary->setTextFormat(Qt::RichText);
    m_checkTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_jack->setObjectName(QStringLiteral("checkJackSpin"));
    m_reference->setObjectName(QStringLiteral("checkReferenceSpin"));
    m_check->setObjectName(QStringLiteral("checkPoint"));
    m_result->setObjectName(QStringLiteral("checkResult"));
    for (QDoubleSpinBox* s : {m_jack, m_reference}) {
        s->setRange(-2000.0, 2000.0);
        s->setDecimals(1);
        s->setMinimumWidth(170);
    }
    auto* grid = new QGridLayout;
    grid->addWidget(m_jackLabel, 0, 0);
    grid->addWidget(m_jack, 0, 1);
    grid->addWidget(m_setJack, 0, 2);
    grid->addWidget(m_referenceLabel, 1, 0);
    grid->addWidget(m_reference, 1, 1);
    grid->addWidget(m_check, 1, 2);
    grid->setColumnStretch(3, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addSpacing(8);
    layout->addWidget(m_checkTitle);
    layout->addLayout(grid);
    layout->addWidget(m_result);
    layout->addStretch(1);
    layout->addWidget(m_accept);
    m_timer->setInterval(ProbeCapturePage::kPollMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) pollProbe();
    });
    connect(m_setJack, &QPushButton::clicked, this, [this] { setJack(m_jack->value()); });
    connect(m_check, &QPushButton::clicked, this, &ProbeAcceptPage::checkPoint);
    connect(m_accept, &QCheckBox::toggled, this, &ProbeAcceptPage::setAccepted);
}

void ProbeAcceptPage::initializePage() {
    DeviceCalibrationProbe* p = m_ctx.probe();
    const bool jack = p && p->hasJack();
    for (QWidget* w : std::initializer_list<QWidget*>{m_jackLabel, m_jack, m_setJack})
        w->setVisible(jack);
    m_reference->setSingleStep(m_ctx.procedure().config().referenceDivisionUm);
    refresh();
    if (p) m_timer->start();
}

void ProbeAcceptPage::cleanupPage() {
    m_timer->stop();
    m_ctx.procedure().abort();  // a check being read
    m_ctx.procedure().takeEvents();
}

bool ProbeAcceptPage::validatePage() {
    return m_ctx.procedure().accepted();
}

bool ProbeAcceptPage::isComplete() const {
    return m_ctx.procedure().accepted();
}

void ProbeAcceptPage::setJack(double um) {
    DeviceCalibrationProbe* p = m_ctx.probe();
    if (!p || !p->hasJack() || m_ctx.procedure().capturing()) return;
    m_jack->setValue(um);
    pollProbe(0.0);  // the samples queued so far were read under the old load
    try {
        p->bendBar(m_ctx.procedure().config().plane, um / 1000.0);
    } catch (const std::invalid_argument&) {
        return;
    }
    const double division = m_ctx.procedure().config().referenceDivisionUm;
    m_reference->setValue(std::round(um / division) * division);
    m_ctx.procedure().loadChanged();
    m_ctx.procedure().takeEvents();
}

void ProbeAcceptPage::setReferenceUm(double um) {
    m_reference->setValue(um);
}

bool ProbeAcceptPage::checkPoint() {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!m_ctx.probe()) return false;
    if (proc.capturing()) {
        proc.abort();
        proc.takeEvents();
        refresh();
        return false;
    }
    proc.withdrawAcceptance();  // a new check may change the verdict
    pollProbe(0.0);             // samples queued before the press are not the check's
    try {
        proc.check(m_reference->value());
    } catch (const std::logic_error&) {
        return false;
    }
    m_result->setText(tr("Hold still, then the live codes are averaged…"));
    markProblem(m_result, false);
    refresh();
    return true;
}

void ProbeAcceptPage::pollProbe(double elapsedS) {
    m_ctx.pumpProbe(elapsedS);
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    bool any = false;
    for (const core::ProbeEvent& e : m_ctx.procedure().takeEvents()) {
        m_result->setText(ProcedureWords::probeEvent(e, c.adcBits, c.capture.noSampleTimeoutS));
        if (e.check)
            markVerdict(m_result, e.check->passed);
        else
            markProblem(m_result, e.kind == core::ProbeEvent::Kind::CaptureFailed);
        any = true;
    }
    if (any) refresh();
}

void ProbeAcceptPage::setAccepted(bool accepted) {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (accepted && !proc.accept()) {
        m_result->setText(
            tr("Not accepted: a verification point failed or is being read. Check again, or go back "
               "and capture more points."));
        markProblem(m_result, true);
    } else if (!accepted) {
        proc.withdrawAcceptance();
    }
    proc.takeEvents();
    refresh();
}

QString ProbeAcceptPage::checkResult() const {
    return m_result->text();
}

void ProbeAcceptPage::refresh() {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    {
        const QSignalBlocker block(m_accept);
        m_accept->setChecked(proc.accepted());
    }
    m_check->setText(proc.capturing() ? tr("Stop") : tr("Check point"));
    m_check->setEnabled(m_ctx.probe() != nullptr && proc.fitOutcome().usable());
    m_setJack->setEnabled(!proc.capturing());
    emit completeChanged();
    if (!proc.fitOutcome().usable()) return;
    const core::Linearisation& lin = *proc.fitOutcome().linearisation;
    DeviceCalibrationProbe* p = m_ctx.probe();
    const QString probe = p ? p->name() : tr("(typed points)");
    const int plane = proc.config().plane;
    const int version = m_ctx.store ? m_ctx.store->nextTableVersion(probe, plane) : 1;
    const double share = static_cast<double>(lin.extrapolatedEntries) /
                         static_cast<double>(std::max<std::size_t>(1, lin.table.entries.size()));
    const QString warning =
        share > core::kExtrapolatedWarningShare
            ? QStringLiteral("<br><b>%1</b>")
                  .arg(tr("%1 % of the table lies outside the calibrated range and is extrapolated; calibrate over "
                          "more of the probe's travel.")
                           .arg(100.0 * share, 0, 'f', 0)
                           .toHtmlEscaped())
            : QString();
    int passed = 0;
    for (const core::ProbeCheck& c : proc.checks())
        passed += c.passed ? 1 : 0;
    const QString checks = proc.checks().empty()
                               ? tr("no verification point yet")
                               : tr("%1 of %2 verification points passed").arg(passed).arg(proc.checks().size());
    const int used = static_cast<int>(proc.points().size() - proc.fitOutcome().leftOut.size());
    m_summary->setText(
        tr("<p>Characteristic of degree %1 from %2 points, residual RMS %3 µm.</p>"
           "<p>Table: %4 entries of %5 nm, worst error at the calibration points %6 µm, step between codes up "
           "to %7 µm; %8 entries outside the calibrated range %9 .. %10 µm are extrapolated.%11</p>"
           "<p>It will be saved as version <b>%12</b> of %13, plane %14, by <b>%15</b>.</p>")
            .arg(lin.fit.degree)
            .arg(used)
            .arg(lin.fit.rmsResidualUm, 0, 'f', 2)
            .arg(lin.table.entries.size())
            .arg(lin.table.scaleNm)
            .arg(lin.maxTableErrorUm, 0, 'f', 2)
            .arg(lin.tableResolutionUm, 0, 'f', 2)
            .arg(lin.extrapolatedEntries)
            .arg(lin.fit.calibratedMinUm, 0, 'f', 0)
            .arg(lin.fit.calibratedMaxUm, 0, 'f', 0)
            .arg(warning)
            .arg(version)
            .arg(probe.toHtmlEscaped())
            .arg(plane == 0 ? QStringLiteral("X") : QStringLiteral("Y"))
            .arg(m_ctx.operatorName().isEmpty() ? tr("(no operator name — set it in Settings)")
                                                : m_ctx.operatorName().toHtmlEscaped()));
    m_checkTitle->setText(tr("Verify the table — %1").arg(checks));
}

void ProbeAcceptPage::retranslate() {
    setTitle(tr("Verify and accept the table"));
    setSubTitle(
        tr("Load the bar to a deflection not captured and check that the table reads it; the table is "
           "stored only when you accept it."));
    m_jackLabel->setText(tr("Stand's screw jack"));
    m_setJack->setText(tr("Bend the bar"));
    m_referenceLabel->setText(tr("Reference reading"));
    for (QDoubleSpinBox* s : {m_jack, m_reference})
        s->setSuffix(tr(" µm"));
    m_accept->setText(tr("I accept this linearisation table"));
    refresh();
}

}  // namespace tt::ui
